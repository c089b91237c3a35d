/*
 * fuzz_scene.c -- libFuzzer harness for the scene reader (fp3_scene_read,
 * sw/scene/objects.c: an `h STEP` line, then `T C m v0 s0` per object).
 *
 * The input is written to DIR/in.scene and read; a scene that reads is
 * checked for what the reader promises (h finite and > 0, the same in every
 * object) and freed.
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

#include "fuzz_common.h"
#include "objects.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  fp3_scene sc;
  char msg[512];
  if (fp3_scene_read(fuzz_write("in.scene", data, size), 0.0f, &sc, msg, sizeof msg) != 0)
    return 0;
  for (size_t i = 0; i < sc.n; i++)
    if (!(isfinite(sc.objs[i].h) && sc.objs[i].h > 0.0f) || sc.objs[i].h != sc.objs[0].h) {
      fprintf(stderr, "fuzz_scene: object %zu has step %g\n", i, (double)sc.objs[i].h);
      abort();
    }
  fp3_scene_free(&sc);
  return 0;
}
