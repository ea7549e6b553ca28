// Coverage of a ray footprint by a strand: the fraction of the footprint that a straight band
// of width w, whose axis passes at distance d from the footprint centre, covers. Every form is
// cov = F(d + w/2) - F(d - w/2), where F is the cumulative distribution of the footprint
// projected onto the band's normal (curve-ray-tracing.md §3). The forms differ in the
// footprint's shape:
//   box    : the seed paper's formula, a 1D box of half-width r          (F linear)
//   disc   : a disc of radius r                                          (F from the chord length)
//   square : the pixel (sample) square spanned by the ray differentials;
//            its projection on the band normal is a trapezoid (the convolution of two boxes),
//            which makes the coverage exact for a straight band under the box pixel filter.
#pragma once

#include <algorithm>
#include <cmath>
#include <numbers>

namespace darc {

enum class CoverageModel { Box, Disc, Square };

// The seed's 1D box CDF over [-r, r].
inline float box_cdf(float x, float r) { return 0.5f + 0.5f * std::clamp(x / r, -1.0f, 1.0f); }

// The fraction of a disc of radius r on the negative side of a line at signed offset x.
inline float disc_cdf(float x, float r) {
  float s = std::clamp(x / r, -1.0f, 1.0f);
  return 0.5f + (std::asin(s) + s * std::sqrt(std::max(0.0f, 1.0f - s * s))) / std::numbers::pi_v<float>;
}

// CDF of the sum of two independent uniforms of full widths a and b (centred): a trapezoid.
inline float trapezoid_cdf(float x, float a, float b) {
  if (a < b) std::swap(a, b);
  if (!(a > 0.0f)) return x >= 0.0f ? 1.0f : 0.0f;
  float ax = std::abs(x);
  float inner = 0.5f * (a - b), outer = 0.5f * (a + b);
  float half_mass;  // mass between 0 and |x|
  if (ax <= inner) {
    half_mass = ax / a;
  } else if (ax < outer) {
    // The flat part, then the ramp (density falling linearly from 1/a to 0 over width b).
    float ramp = ax - inner;
    half_mass = inner / a + (ramp - ramp * ramp / (2.0f * b)) / a;
  } else {
    half_mass = 0.5f;
  }
  half_mass = std::min(half_mass, 0.5f);
  return x >= 0.0f ? 0.5f + half_mass : 0.5f - half_mass;
}

// The seed's coverage (box footprint of radius r).
inline float coverage_box(float d, float half_width, float r) {
  return std::clamp(box_cdf(d + half_width, r) - box_cdf(d - half_width, r), 0.0f, 1.0f);
}

// A disc footprint of radius r.
inline float coverage_disc(float d, float half_width, float r) {
  return std::clamp(disc_cdf(d + half_width, r) - disc_cdf(d - half_width, r), 0.0f, 1.0f);
}

// A square footprint whose extents across the band (its sides projected on the band normal)
// are a and b.
inline float coverage_square(float d, float half_width, float a, float b) {
  return std::clamp(trapezoid_cdf(d + half_width, a, b) - trapezoid_cdf(d - half_width, a, b), 0.0f, 1.0f);
}

}  // namespace darc
