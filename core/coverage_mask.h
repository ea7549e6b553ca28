// Coverage masks: which of 8 x 8 regularly placed points of a footprint square a strand covers.
// Scalar coverage alone cannot tell two strands that overlap from two that abut
// (curve-ray-tracing.md §6 case 8: two abutting 50 % strands composite to 75 %, not 100 %).
// A fragment carries both: its exact scalar coverage says how much, its mask says where, and
// the A-buffer composites per mask point with the scalar spread over the fragment's points.
#pragma once

#include <bit>
#include <cstdint>

namespace darc {

inline constexpr int kMaskSide = 8;  // 8 x 8 points: one 64-bit word per fragment
using CoverageMask = uint64_t;
inline constexpr CoverageMask kFullMask = ~CoverageMask{0};

inline int mask_count(CoverageMask m) { return std::popcount(m); }

// The footprint square in 2D (the plane perpendicular to the ray, centred on the ray): its
// sides are the vectors (ax_x, ax_y) and (ay_x, ay_y).
struct FootprintSquare {
  float ax_x, ax_y, ay_x, ay_y;
};

// Points p of the square for which |dot(p - c, n)| <= half_width, where c is a point on the
// strand axis and n the unit normal of the axis (all 2D, relative to the ray).
inline CoverageMask band_mask(const FootprintSquare& sq, float cx, float cy, float nx, float ny, float half_width) {
  // The signed distance is affine in the point's grid coordinates: s = s0 + i*si + j*sj.
  const float step = 1.0f / kMaskSide;
  float ani = (sq.ax_x * nx + sq.ax_y * ny) * step;
  float anj = (sq.ay_x * nx + sq.ay_y * ny) * step;
  float s0 = -(cx * nx + cy * ny) - 0.5f * (kMaskSide - 1) * (ani + anj);
  CoverageMask m = 0;
  for (int j = 0; j < kMaskSide; ++j) {
    float s = s0 + float(j) * anj;
    for (int i = 0; i < kMaskSide; ++i, s += ani)
      if (s <= half_width && s >= -half_width) m |= CoverageMask{1} << (j * kMaskSide + i);
  }
  return m;
}

// Points p of the square on the strand's side of an end line through e with unit direction
// (tx, ty) pointing into the strand: dot(p - e, t) >= 0.
inline CoverageMask half_plane_mask(const FootprintSquare& sq, float ex, float ey, float tx, float ty) {
  const float step = 1.0f / kMaskSide;
  float ati = (sq.ax_x * tx + sq.ax_y * ty) * step;
  float atj = (sq.ay_x * tx + sq.ay_y * ty) * step;
  float s0 = -(ex * tx + ey * ty) - 0.5f * (kMaskSide - 1) * (ati + atj);
  CoverageMask m = 0;
  for (int j = 0; j < kMaskSide; ++j) {
    float s = s0 + float(j) * atj;
    for (int i = 0; i < kMaskSide; ++i, s += ati)
      if (s >= 0.0f) m |= CoverageMask{1} << (j * kMaskSide + i);
  }
  return m;
}

}  // namespace darc
