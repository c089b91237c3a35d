/*
 * fuzz_common.c -- helpers shared by the libFuzzer harnesses (fuzz_common.h).
 */
#define _DEFAULT_SOURCE /* mkdtemp */
#include "fuzz_common.h"

#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

static char dir[64];

/* atexit: remove the files the harness wrote, then the folder. */
static void remove_dir(void) {
  DIR *d = opendir(dir);
  if (d) {
    struct dirent *e;
    while ((e = readdir(d)) != NULL)
      if (strcmp(e->d_name, ".") != 0 && strcmp(e->d_name, "..") != 0) unlink(fuzz_path(e->d_name));
    closedir(d);
  }
  rmdir(dir);
}

const char *fuzz_dir(void) {
  if (dir[0]) return dir;
  /* tmpfs when there is one: a write per input to a disk-backed /tmp
   * costs milliseconds, a hundred times the parse. */
  struct stat sb;
  const char *base = stat("/dev/shm", &sb) == 0 && S_ISDIR(sb.st_mode) ? "/dev/shm" : "/tmp";
  snprintf(dir, sizeof dir, "%s/fp3-fuzz-XXXXXX", base);
  if (!mkdtemp(dir)) {
    perror("fuzz: mkdtemp");
    abort();
  }
  atexit(remove_dir);
  return dir;
}

const char *fuzz_path(const char *name) {
  static char path[512];
  snprintf(path, sizeof path, "%s/%s", fuzz_dir(), name);
  return path;
}

const char *fuzz_write(const char *name, const uint8_t *data, size_t n) {
  const char *path = fuzz_path(name);
  FILE *f = fopen(path, "wb");
  if (!f || (n && fwrite(data, 1, n, f) != n) || fclose(f) != 0) {
    perror(path);
    abort();
  }
  return path;
}

char *fuzz_strdup(const uint8_t *data, size_t n) {
  char *s = malloc(n + 1);
  if (!s) abort();
  memcpy(s, data, n);
  s[n] = '\0';
  return s;
}
