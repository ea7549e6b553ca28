// The slab test of one ray against four boxes at once: the inner step of the 4-wide BVH. Two
// implementations that give bitwise the same results: SSE (x86-64 has SSE2 in its baseline, so
// no -march flag is involved and golden images do not depend on the CPU) and a portable loop
// (other architectures, and the test that checks the two agree: tests/core/accel/bvh_test.cpp).
//
// Bitwise agreement holds because both do the same IEEE single-precision operations in the same
// order (no fused multiply-add: the build never enables FMA), and the SSE min/max instructions
// return their second operand when either is NaN, which is what the scalar forms below return.
#pragma once

#include <cstdint>

#include "core/math/ray.h"

#if defined(__SSE2__)
#include <emmintrin.h>
#define DARC_SLAB4_SSE 1
#endif

namespace darc {

struct alignas(16) Slab4Boxes {
  float lo_x[4], lo_y[4], lo_z[4], hi_x[4], hi_y[4], hi_z[4];
};

// A ray prepared for slab tests: its origin and inverse direction (components of d equal to zero
// give infinities; a resulting 0 * inf is NaN, which never rejects).
struct Slab4Ray {
  float ox, oy, oz, ix, iy, iz;
  explicit Slab4Ray(const Ray& r)
      : ox(r.o.x), oy(r.o.y), oz(r.o.z), ix(1.0f / r.d.x), iy(1.0f / r.d.y), iz(1.0f / r.d.z) {}
};

struct Slab4Result {
  alignas(16) float t0[4];
  alignas(16) float t1[4];
  unsigned mask;  // bit k: the ray's interval through box k (grown) is not empty
};

// The portable form: for each box, the interval [t0, t1] of the ray inside the box grown by
// `grow`, clipped to [tmin, tmax].
inline Slab4Result slab4_portable(const Slab4Ray& r, const Slab4Boxes& b, float grow, float tmin, float tmax) {
  Slab4Result out;
  out.mask = 0;
  for (int k = 0; k < 4; ++k) {
    float t0 = tmin, t1 = tmax;
    auto axis = [&](float lo, float hi, float o, float inv) {
      float a = (lo - grow - o) * inv, c = (hi + grow - o) * inv;
      float n = c < a ? c : a, f = c > a ? c : a;  // = _mm_min_ps(c, a), _mm_max_ps(c, a)
      t0 = n > t0 ? n : t0;                          // = _mm_max_ps(n, t0): NaN keeps t0
      t1 = f < t1 ? f : t1;                          // = _mm_min_ps(f, t1): NaN keeps t1
    };
    axis(b.lo_x[k], b.hi_x[k], r.ox, r.ix);
    axis(b.lo_y[k], b.hi_y[k], r.oy, r.iy);
    axis(b.lo_z[k], b.hi_z[k], r.oz, r.iz);
    out.t0[k] = t0;
    out.t1[k] = t1;
    if (t0 <= t1) out.mask |= 1u << k;
  }
  return out;
}

#ifdef DARC_SLAB4_SSE
inline Slab4Result slab4_sse(const Slab4Ray& r, const Slab4Boxes& b, float grow, float tmin, float tmax) {
  const __m128 g = _mm_set1_ps(grow);
  __m128 t0 = _mm_set1_ps(tmin), t1 = _mm_set1_ps(tmax);
  auto axis = [&](const float* lo, const float* hi, float o, float inv) {
    const __m128 vo = _mm_set1_ps(o), vi = _mm_set1_ps(inv);
    __m128 a = _mm_mul_ps(_mm_sub_ps(_mm_sub_ps(_mm_load_ps(lo), g), vo), vi);
    __m128 c = _mm_mul_ps(_mm_sub_ps(_mm_add_ps(_mm_load_ps(hi), g), vo), vi);
    __m128 n = _mm_min_ps(c, a), f = _mm_max_ps(c, a);
    t0 = _mm_max_ps(n, t0);
    t1 = _mm_min_ps(f, t1);
  };
  axis(b.lo_x, b.hi_x, r.ox, r.ix);
  axis(b.lo_y, b.hi_y, r.oy, r.iy);
  axis(b.lo_z, b.hi_z, r.oz, r.iz);
  Slab4Result out;
  _mm_store_ps(out.t0, t0);
  _mm_store_ps(out.t1, t1);
  out.mask = unsigned(_mm_movemask_ps(_mm_cmple_ps(t0, t1)));
  return out;
}
#endif

inline Slab4Result slab4(const Slab4Ray& r, const Slab4Boxes& b, float grow, float tmin, float tmax) {
#ifdef DARC_SLAB4_SSE
  return slab4_sse(r, b, grow, tmin, tmax);
#else
  return slab4_portable(r, b, grow, tmin, tmax);
#endif
}

}  // namespace darc
