/*
 * cmd_frames.h -- `fp3 frames`: a scene run frame by frame with sleeping
 * objects (mscene.h fp3_run_state_frames), on the one path of `fp3 run`
 * (runsetup.h), and its report (fp3 frames --help, docs/skipping.md).
 */
#ifndef FP3_CMD_FRAMES_H
#define FP3_CMD_FRAMES_H

/* argv[0] is "frames".  Returns the exit status: 0 every object equals
 * its golden model after every frame, 1 a mismatch, a context error or an
 * engine failure, 2 bad arguments, scene, model or program (a message on
 * stderr). */
int fp3_cmd_frames(int argc, char **argv);

#endif /* FP3_CMD_FRAMES_H */
