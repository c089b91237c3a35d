/*
 * cmd_run.h -- `fp3 run`: a model's program on the RTL or the ISS, every
 * state variable checked bit for bit against the golden model after every
 * integration (fp3 run --help; options: fp3_model_args, cmd_model.h).
 */
#ifndef FP3_CMD_RUN_H
#define FP3_CMD_RUN_H

#define FP3_RUN_DEFAULT_STEPS 10000u /* --steps: integrations            */

/* argv[0] is "run".  Exit status: 0 the run finished without error and
 * bit-exact with the golden model, 1 it did not (or a state went
 * non-finite), 2 bad arguments, model or program (a message on stderr
 * naming the file and line). */
int fp3_cmd_run(int argc, char **argv);

#endif /* FP3_CMD_RUN_H */
