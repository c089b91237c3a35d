/*
 * fp3.c -- the FP3 command line.
 *
 *   fp3 asm FILE.s [-o FILE.hex]     assemble to a $readmemh image
 *   fp3 disasm FILE.hex              image to assembly text
 *   fp3 run [options]                run a program on an engine and check
 *                                    every integration against the golden
 *                                    model, bit for bit
 *   fp3 testfloat ...                FP cores against TestFloat vectors
 *   fp3 bench [--model FILE] [...]   a model's integrators (default the
 *                                    ship): work-precision, Pareto table,
 *                                    stability, long runs (cmd_bench.c)
 *   fp3 tbgen FILE.s -o DIR          files of the Icarus testbench
 *   fp3 compile SCENE|--model FILE   a program compiled for a model or scene
 *                                    (sw/compiler/compile.h)
 *   fp3 spatial MODEL -o DIR         a model's integration step as one
 *                                    pipelined Verilog module
 *                                    (sw/compiler/spatial.h)
 *   fp3 configure SCENE [-o FILE]    RTL parameters sized to the scene
 *                                    (sw/compiler/configure.h)
 *   fp3 frames [options]             a scene frame by frame with sleeping
 *                                    objects (sw/scene/mscene.h)
 *
 * Each subcommand is sw/cli/cmd_NAME.c: its parse step (fp3_parse_NAME,
 * cliopt.h) and its run step; this file only dispatches.
 *
 * Exit status: 0 success; 1 the run failed (engine error, golden mismatch);
 * 2 bad arguments or input (usage, parameters, assembly errors).
 */
#include <stdio.h>
#include <string.h>

#include "cliopt.h"
#include "cmd_asm.h"
#include "cmd_bench.h"
#include "cmd_compile.h"
#include "cmd_spatial.h"
#include "cmd_configure.h"
#include "cmd_disasm.h"
#include "cmd_frames.h"
#include "cmd_model.h"
#include "cmd_run.h"
#include "cmd_tbgen.h"
#include "cmd_testfloat.h"
#ifdef FP3_MPI
#include "mpishard.h"
#endif

#define EXIT_USAGE 2

/* ---- main --------------------------------------------------------------- */

static void usage(FILE *f) {
  fprintf(f,
          "usage: fp3 COMMAND [ARGS]   (fp3 COMMAND --help for each)\n"
          "\n"
          "  asm FILE.s [-o FILE.hex]  assemble a program\n"
          "  disasm FILE.hex           disassemble a program image\n"
          "  run [options]             run a model's program on the RTL, the ISS or\n"
          "                            its spatial pipeline (--engine spatial)\n"
          "                            and check it bit for bit against the golden\n"
          "                            model (default: the paper's ship RK4)\n"
          "  testfloat ...             FP cores against TestFloat vectors\n"
          "  bench [--model FILE]      a model's integrators (default: the ship):\n"
          "                            work-precision, Pareto table, stability\n"
          "                            bounds, long runs\n"
          "  tbgen FILE.s -o DIR       files of the Icarus testbench (make wave)\n"
          "  compile SCENE|--model M   a model or a scene compiled into a program\n"
          "                            (fp3 run compiles it itself)\n"
          "  spatial MODEL -o DIR      a model's integration step as a pipelined\n"
          "                            Verilog module, one object per cycle\n"
          "  configure SCENE [-o FILE] RTL parameters sized to the scene\n"
          "                            (make variables; make synth-scene)\n"
          "  frames [options]          a scene frame by frame with sleeping\n"
          "                            objects (make bench-sleep)\n");
#ifdef FP3_MPI
  fprintf(f,
          "\n"
          "fp3-mpi (mpirun -np N build/fp3-mpi COMMAND ...): run of many objects and\n"
          "frames shard the objects across the N ranks in whole batches of contexts x\n"
          "lanes, rank 0 printing what one process prints and, on stderr, a line per\n"
          "rank; the other commands run on rank 0.  FP3_MPI_FAULT=engine|golden|kill:OBJECT\n"
          "makes the rank holding OBJECT fail on purpose (docs/cluster.md).\n");
#endif
}

static int dispatch(int argc, char **argv);

/* build/fp3-mpi (-DFP3_MPI, docs/cluster.md): every rank runs the command;
 * run and frames shard their objects across the ranks (mpishard.h), and
 * only rank 0 writes standard output.  The exit status is the largest of
 * the ranks'. */
int main(int argc, char **argv) {
#ifdef FP3_MPI
  if (fp3_mpi_init(&argc, &argv)) return fp3_mpi_finish(EXIT_USAGE);
  return fp3_mpi_finish(dispatch(argc, argv));
#else
  return dispatch(argc, argv);
#endif
}

static int dispatch(int argc, char **argv) {
  if (argc < 2) {
    usage(stderr);
    return EXIT_USAGE;
  }
  const char *cmd = argv[1];
  if (fp3_is_help(cmd) || strcmp(cmd, "help") == 0) {
    usage(stdout);
    return 0;
  }
  if (strcmp(cmd, "asm") == 0) return fp3_cmd_asm(argc - 1, argv + 1);
  if (strcmp(cmd, "disasm") == 0) return fp3_cmd_disasm(argc - 1, argv + 1);
  if (strcmp(cmd, "run") == 0) return fp3_cmd_run(argc - 1, argv + 1);
  if (strcmp(cmd, "testfloat") == 0)
    return fp3_cmd_testfloat(argc - 1, argv + 1);
  if (strcmp(cmd, "tbgen") == 0) return fp3_cmd_tbgen(argc - 1, argv + 1);
  if (strcmp(cmd, "compile") == 0) return fp3_cmd_compile(argc - 1, argv + 1);
  if (strcmp(cmd, "spatial") == 0) return fp3_cmd_spatial(argc - 1, argv + 1);
  if (strcmp(cmd, "configure") == 0) return fp3_cmd_configure(argc - 1, argv + 1);
  if (strcmp(cmd, "bench") == 0) return fp3_cmd_bench(argc - 1, argv + 1);
  if (strcmp(cmd, "frames") == 0) return fp3_cmd_frames(argc - 1, argv + 1);
  fprintf(stderr, "fp3: unknown command '%s' (see fp3 --help)\n", cmd);
  return EXIT_USAGE;
}
