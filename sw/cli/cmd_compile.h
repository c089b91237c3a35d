/*
 * cmd_compile.h -- `fp3 compile SCENE`: the scene compiler (compile.h) on
 * the command line.
 */
#ifndef FP3_CMD_COMPILE_H
#define FP3_CMD_COMPILE_H

/* argv[0] is "compile".  Returns the exit status: 0 written, 1 the output
 * could not be written, 2 bad arguments, scene or integrator (a message on
 * stderr). */
int fp3_cmd_compile(int argc, char **argv);

#endif /* FP3_CMD_COMPILE_H */
