/*
 * fuzz_common.h -- helpers shared by the libFuzzer harnesses (fuzz/fuzz_*.c).
 *
 * Several parsers read a file by path (the program-image, scene and
 * TestFloat readers, the assembler with `.include`).  Their harnesses write
 * each input to a file in a private temporary folder, created once per
 * fuzzing process and removed at exit, and hand the parser that path, so
 * that the code under test is the same as for a user's file (fopen, fgets,
 * line-length checks, gzip detection).
 */
#ifndef FP3_FUZZ_COMMON_H
#define FP3_FUZZ_COMMON_H

#include <stddef.h>
#include <stdint.h>

/* The process's temporary folder ("/dev/shm/fp3-fuzz-XXXXXX", in /tmp
 * when there is no /dev/shm), created on the
 * first call; aborts if it cannot be created (the harness cannot run). */
const char *fuzz_dir(void);

/* Path of `name` inside fuzz_dir(), in a static buffer (valid until the
 * next call). */
const char *fuzz_path(const char *name);

/* Write data[0..n) to fuzz_path(name), replacing the file; returns the
 * path.  Aborts on a write error (a full disk is not a parser bug). */
const char *fuzz_write(const char *name, const uint8_t *data, size_t n);

/* data[0..n) as a NUL-terminated malloc'd string (an embedded NUL ends the
 * text early, as it would for a C reader); the caller frees it. */
char *fuzz_strdup(const uint8_t *data, size_t n);

#endif /* FP3_FUZZ_COMMON_H */
