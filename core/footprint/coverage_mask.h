// Coverage masks: which of 8 x 8 regularly placed points of a footprint square a strand covers.
// Scalar coverage alone cannot tell two strands that overlap from two that abut
// (curve-ray-tracing.md §6 case 8: two abutting 50 % strands composite to 75 %, not 100 %).
// A fragment carries both: its exact scalar coverage says how much, its mask says where, and
// the A-buffer composites per mask point with the scalar spread over the fragment's points.
#pragma once

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

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

// How many mask points a fragment of coverage c takes: enough to hold it (c * 64 rounded up, but
// for a rounding's worth), so that its opacity per point stays at most 1 and nothing is left
// over. Rounded to nearest, a clump of strands slightly wider than a whole number of points each
// left a remainder beside the same mask, and a hundred remainders filled the points around it
// (the scalp's silhouette: alpha 0.28 where the clump covers 0.10).
inline int mask_points_for(float coverage) {
  constexpr int kPoints = kMaskSide * kMaskSide;
  return std::clamp(int(std::ceil(coverage * float(kPoints) - 1e-3f)), 1, kPoints);
}

// The points p of the square whose signed distance dot(p - c, n) to the line through c with
// unit normal n (all 2D, relative to the ray) satisfies `keep`. The distance is affine in the
// point's grid coordinates, s = s0 + i*si + j*sj, so it is stepped, not recomputed.
template <class Keep>
CoverageMask line_distance_mask(const FootprintSquare& sq, float cx, float cy, float nx, float ny, Keep&& keep) {
  const float step = 1.0f / kMaskSide;
  float si = (sq.ax_x * nx + sq.ax_y * ny) * step;
  float sj = (sq.ay_x * nx + sq.ay_y * ny) * step;
  float s0 = -(cx * nx + cy * ny) - 0.5f * (kMaskSide - 1) * (si + sj);
  CoverageMask m = 0;
  for (int j = 0; j < kMaskSide; ++j) {
    float s = s0 + float(j) * sj;
    for (int i = 0; i < kMaskSide; ++i, s += si)
      if (keep(s)) m |= CoverageMask{1} << (j * kMaskSide + i);
  }
  return m;
}

// Points of the band |dot(p - c, n)| <= half_width around a strand axis through c.
inline CoverageMask band_mask(const FootprintSquare& sq, float cx, float cy, float nx, float ny, float half_width) {
  return line_distance_mask(sq, cx, cy, nx, ny, [&](float s) { return s <= half_width && s >= -half_width; });
}

// Points on the strand's side of an end line through e with unit direction (tx, ty) pointing
// into the strand: dot(p - e, t) >= 0.
inline CoverageMask half_plane_mask(const FootprintSquare& sq, float ex, float ey, float tx, float ty) {
  return line_distance_mask(sq, ex, ey, tx, ty, [](float s) { return s >= 0.0f; });
}

// Motion blur: each mask point also stands for one time of the shutter, so that a strand that
// sweeps across the footprint covers the points it passes when it passes them (two strands
// moving together a little apart cover different points: they add up, as they cover the
// footprint at different times; composited as if independent, they would not). The 64 times are
// (k + 1/2) / 64 for a permutation k of the points in which every row and every column of the
// grid holds each eighth of the shutter once: k = 8 ((i + 3j) mod 8) + ((2i + j) mod 8).
inline float mask_point_time(int point) {
  const int i = point % kMaskSide, j = point / kMaskSide;
  const int k = kMaskSide * ((i + 3 * j) % kMaskSide) + ((2 * i + j) % kMaskSide);
  return (float(k) + 0.5f) / float(kMaskSide * kMaskSide);
}

// A strand axis that moves across the footprint during the shutter times [t0, t1) ([t0, t1] for
// the last interval, `to_close`): its line is offset along its normal by d0 at t0 and by d1 at
// t1 (linearly between) from where it is given.
struct SweptLine {
  float t0 = 0, t1 = 1;
  float d0 = 0, d1 = 0;
  bool to_close = false;
};

// Up to this many points are selected by insertion into a short sorted list.
inline constexpr int kSmallSelection = 12;

// The `count` points of the square nearest to a strand, among the `allowed` ones: nearest to
// the axis line through c with unit normal n (a band), or to the point c itself when `point`
// is set (a strand seen end-on). Choosing the mask by count rather than by a width threshold
// makes its size match the exact coverage to 1/64, so fragments in the same place share points
// (they occlude each other) and fragments side by side do not (they add up). Ties go to the
// lower point index, so masks are deterministic.
// With `sweep`, a point is nearest to the line where it is at the point's time (mask_point_time),
// and points whose times lie outside the sweep's are not allowed.
inline CoverageMask nearest_points_mask(const FootprintSquare& sq, float cx, float cy, float nx, float ny, bool point,
                                        int count, CoverageMask allowed, const SweptLine* sweep = nullptr) {
  constexpr int kPoints = kMaskSide * kMaskSide;
  count = std::clamp(count, 0, kPoints);
  if (count == 0) return 0;
  // Keys order by distance, then by point index: a non-negative float's bits order as the float
  // does, so (bits << 32 | index) compares as the pair, in one integer comparison. The `count`
  // smallest keys are a set (the keys are distinct), so how they are selected does not change it.
  std::array<uint64_t, kPoints> key;
  constexpr uint64_t kInfinityKey = uint64_t(std::bit_cast<uint32_t>(std::numeric_limits<float>::infinity())) << 32;
  // The distances first, one branch-free loop per kind (so that the compiler vectorizes the
  // common one, the band), in the same operations for every point whichever loop runs.
  std::array<float, kPoints> dist;
  const float step = 1.0f / kMaskSide;
  for (int j = 0; j < kMaskSide; ++j) {
    const float v = (float(j) + 0.5f) * step - 0.5f;
    const float row_x = v * sq.ay_x, row_y = v * sq.ay_y;
    float* d = dist.data() + j * kMaskSide;
    if (sweep) {
      for (int i = 0; i < kMaskSide; ++i) {
        const float u = (float(i) + 0.5f) * step - 0.5f;
        const float px = u * sq.ax_x + row_x - cx, py = u * sq.ax_y + row_y - cy;
        const float t = mask_point_time(j * kMaskSide + i);
        const float span = sweep->t1 - sweep->t0;
        if (t < sweep->t0 || (t >= sweep->t1 && !sweep->to_close) || !(span > 0.0f)) {
          d[i] = std::numeric_limits<float>::infinity();
        } else {
          const float offset = sweep->d0 + (sweep->d1 - sweep->d0) * ((t - sweep->t0) / span);
          d[i] = std::abs(px * nx + py * ny - offset);
        }
      }
    } else if (point) {
      for (int i = 0; i < kMaskSide; ++i) {
        const float u = (float(i) + 0.5f) * step - 0.5f;
        const float px = u * sq.ax_x + row_x - cx, py = u * sq.ax_y + row_y - cy;
        d[i] = px * px + py * py;
      }
    } else {
      for (int i = 0; i < kMaskSide; ++i) {
        const float u = (float(i) + 0.5f) * step - 0.5f;
        const float px = u * sq.ax_x + row_x - cx, py = u * sq.ax_y + row_y - cy;
        d[i] = std::abs(px * nx + py * ny);
      }
    }
  }
  for (int b = 0; b < kPoints; ++b) {
    float d = dist[size_t(b)];
    if (!((allowed >> b) & 1) || !(d <= std::numeric_limits<float>::max())) d = std::numeric_limits<float>::infinity();
    key[size_t(b)] = (uint64_t(std::bit_cast<uint32_t>(d)) << 32) | uint64_t(b);
  }
  CoverageMask m = 0;
  if (count <= kSmallSelection) {
    // Thin strands want a few points: keep the best `count` in order, most keys rejected by one
    // comparison with the worst kept (nth_element over all 64 was a fifth of a lens footprint's
    // segment tests).
    std::array<uint64_t, kSmallSelection> best;
    int kept = 0;
    for (const uint64_t k : key) {
      if (kept == count && !(k < best[size_t(count - 1)])) continue;
      int at = kept == count ? count - 1 : kept++;
      while (at > 0 && best[size_t(at - 1)] > k) {
        best[size_t(at)] = best[size_t(at - 1)];
        --at;
      }
      best[size_t(at)] = k;
    }
    for (int k = 0; k < kept; ++k)
      if (best[size_t(k)] < kInfinityKey) m |= CoverageMask{1} << (best[size_t(k)] & 63);
    return m;
  }
  // Linear-time selection.
  std::nth_element(key.begin(), key.begin() + (count - 1), key.end());
  for (int k = 0; k < count; ++k)
    if (key[k] < kInfinityKey) m |= CoverageMask{1} << (key[k] & 63);
  return m;
}

// The mask grown by one point in every direction (the eight neighbours of each point).
inline CoverageMask dilate_mask(CoverageMask m) {
  constexpr CoverageMask kNotFirstColumn = 0xfefefefefefefefeull, kNotLastColumn = 0x7f7f7f7f7f7f7f7full;
  const CoverageMask row = m | ((m << 1) & kNotFirstColumn) | ((m >> 1) & kNotLastColumn);
  return row | (row << kMaskSide) | (row >> kMaskSide);
}

// How a fragment's coverage is spread over the footprint's points: opacity `full_opacity` on
// `full`, `ring_opacity` on `ring`, none elsewhere. Within its mask when the mask holds it;
// what the mask cannot hold (a mask rounds its count, and pieces of a strand add coverages over
// a union of masks) goes to the mask's nearest neighbours, ring after ring, not over the whole
// footprint: hundreds of strands grazing a head's silhouette, each with half a point of excess,
// spread over all 64 points, filled the footprint (alpha 0.57 where they cover 0.3).
struct CoverageSpread {
  CoverageMask full = 0, ring = 0;
  float full_opacity = 0, ring_opacity = 0;
  float at(int b) const { return (full >> b) & 1 ? full_opacity : (ring >> b) & 1 ? ring_opacity : 0.0f; }
};

inline CoverageSpread spread_coverage(CoverageMask mask, float coverage) {
  constexpr int kPoints = kMaskSide * kMaskSide;
  const float c = std::clamp(coverage, 0.0f, 1.0f) * kPoints;
  const int k = mask_count(mask);
  if (k == 0) return {0, kFullMask, 0.0f, c / kPoints};  // nowhere in particular: everywhere
  if (c <= float(k)) return {mask, 0, c / float(k), 0.0f};
  CoverageSpread s{mask, 0, 1.0f, 0.0f};
  float rest = c - float(k);
  for (;;) {
    const CoverageMask ring = dilate_mask(s.full) & ~s.full;
    const int r = mask_count(ring);
    if (r == 0) return s;  // the whole footprint: the rest is rounding
    if (rest <= float(r)) {
      s.ring = ring;
      s.ring_opacity = rest / float(r);
      return s;
    }
    s.full |= ring;
    rest -= float(r);
  }
}

}  // namespace darc
