/*
 * cmd_configure.h -- `fp3 configure SCENE`: the RTL parameters a scene
 * needs (configure.h) on the command line.
 */
#ifndef FP3_CMD_CONFIGURE_H
#define FP3_CMD_CONFIGURE_H

/* argv[0] is "configure".  Returns the exit status: 0 derived (and
 * written), 1 the output could not be written, 2 bad arguments, scene,
 * integrator or budget (a message on stderr). */
int fp3_cmd_configure(int argc, char **argv);

#endif /* FP3_CMD_CONFIGURE_H */
