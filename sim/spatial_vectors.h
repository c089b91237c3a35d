// spatial_vectors.h -- the reader of the test vectors `fp3 spatial
// --vectors N --steps K` writes (sw/compiler/spatial.h fp3_spatial_vectors),
// for the harnesses sim/spatial_tb.cpp and sim/spatial_chip_tb.cpp.
#ifndef FP3_SPATIAL_VECTORS_H
#define FP3_SPATIAL_VECTORS_H

#include <cstdint>
#include <cstdio>
#include <vector>

struct spatial_vectors {
  unsigned long nobj, steps, nin, nc, lat; // objects, steps, inputs, carried, latency
  std::vector<uint32_t> in;   // object o's input k at [o * nin + k]
  std::vector<uint32_t> y0;   // its initial carried value w at [o * nc + w]
  std::vector<uint32_t> gold; // after step s (0-based): [(s * nobj + o) * nc + w]
};

// Read the file at path into *v: 0, or -1 with a message on stderr (no
// file, not a vectors file, too short).
static inline int spatial_vectors_read(const char *path, spatial_vectors *v) {
  FILE *f = std::fopen(path, "r");
  if (!f) {
    std::perror(path);
    return -1;
  }
  if (std::fscanf(f, "fp3-spatial-vectors %lu %lu %lu %lu %lu", &v->nobj, &v->steps, &v->nin,
                  &v->nc, &v->lat) != 5) {
    std::fprintf(stderr, "%s: not a vectors file\n", path);
    std::fclose(f);
    return -1;
  }
  v->in.assign(v->nobj * v->nin, 0);
  v->y0.assign(v->nobj * v->nc, 0);
  v->gold.assign(v->steps * v->nobj * v->nc, 0);
  bool ok = true;
  auto rd = [&](uint32_t &w) {
    unsigned x;
    if (ok && std::fscanf(f, "%x", &x) == 1) w = x;
    else ok = false;
  };
  for (unsigned long o = 0; o < v->nobj; o++) {
    for (unsigned long k = 0; k < v->nin; k++) rd(v->in[o * v->nin + k]);
    for (unsigned long w = 0; w < v->nc; w++) rd(v->y0[o * v->nc + w]);
  }
  for (auto &w : v->gold) rd(w);
  std::fclose(f);
  if (!ok) std::fprintf(stderr, "%s: short vectors file\n", path);
  return ok ? 0 : -1;
}

#endif // FP3_SPATIAL_VECTORS_H
