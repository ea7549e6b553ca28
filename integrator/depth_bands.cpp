#include "integrator/depth_bands.h"

#include <algorithm>
#include <cmath>

namespace darc {

namespace {

// The bilinear depth at mask point b from the corner mask points' depths (SurfaceFragment).
float depth_at_point(const SurfaceFragment& sf, int b) {
  const float s = float(b % kMaskSide) / float(kMaskSide - 1), r = float(b / kMaskSide) / float(kMaskSide - 1);
  const auto& c = sf.corner_t;
  return (1 - r) * ((1 - s) * c[0] + s * c[1]) + r * ((1 - s) * c[2] + s * c[3]);
}

}  // namespace

DepthBands depth_bands(const SurfaceFragment& sf) {
  DepthBands out;
  const auto [lo, hi] = std::minmax_element(sf.corner_t.begin(), sf.corner_t.end());
  const float range = *hi - *lo, depth = std::abs(sf.t);
  if (!(range > kDepthBandFraction * depth) || !std::isfinite(range)) return out;
  const int count = std::min(kMaxDepthBands, int(std::ceil(range / (kDepthBandFraction * depth))));
  std::array<float, kMaxDepthBands> sum_t{}, sum_u{}, sum_v{};
  std::array<int, kMaxDepthBands> points{};
  std::array<CoverageMask, kMaxDepthBands> masks{};
  std::array<float, kMaskSide * kMaskSide> depth_of{};
  std::array<int, kMaskSide * kMaskSide> band_of{};
  for (int b = 0; b < kMaskSide * kMaskSide; ++b) {
    const float t = depth_at_point(sf, b);
    const int k = std::clamp(int((t - *lo) / range * float(count)), 0, count - 1);
    depth_of[size_t(b)] = t;
    band_of[size_t(b)] = k;
    sum_t[size_t(k)] += t;
    sum_u[size_t(k)] += float(b % kMaskSide);
    sum_v[size_t(k)] += float(b / kMaskSide);
    ++points[size_t(k)];
    masks[size_t(k)] |= CoverageMask{1} << b;
  }
  for (int k = 0; k < count; ++k) {
    const int n = points[size_t(k)];
    if (n == 0) continue;
    DepthBand& band = out.band[size_t(out.count++)];
    band.t = sum_t[size_t(k)] / float(n);
    band.coverage = float(n) / float(kMaskSide * kMaskSide);
    band.mask = masks[size_t(k)];
    const float cu = sum_u[size_t(k)] / float(n), cv = sum_v[size_t(k)] / float(n);
    float best = std::numeric_limits<float>::infinity();
    for (int b = 0; b < kMaskSide * kMaskSide; ++b) {
      if (band_of[size_t(b)] != k) continue;
      const float du = float(b % kMaskSide) - cu, dv = float(b / kMaskSide) - cv;
      if (du * du + dv * dv < best) best = du * du + dv * dv, band.point = b;
    }
    out.nearest = std::min(out.nearest, band.t);
  }
  return out;
}

// The farthest depth of a surface that covers the whole footprint: its corner mask points'
// depths carried out to the footprint's corners (half a cell farther from the centre).
float farthest_depth(const SurfaceFragment& sf) {
  float far = sf.t;
  const float out_to_corner = float(kMaskSide) / float(kMaskSide - 1);
  for (float t : sf.corner_t) far = std::max(far, sf.t + (t - sf.t) * out_to_corner);
  return far;
}

}  // namespace darc
