// Coverage of a footprint by a band that moves across it during the shutter, averaged over the
// shutter in closed form (motion-and-programs.md A3.1): the static coverage is
// c(d) = F(d + h) - F(d - h) for the footprint's CDF F across the band, and with the band's
// axis moving linearly from d0 to d1 its average over time is one more integration,
//   [G(d1 + h) - G(d0 + h) - G(d1 - h) + G(d0 - h)] / (d1 - d0),   G' = F.
// A box in time is a segment in space: a thin strand swept L footprints across leaves its width
// over L on every footprint inside the sweep, as a camera with an open shutter sees it.
// Evaluated in double: the difference quotient loses digits as d1 - d0 shrinks.
#pragma once

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/footprint/coverage.h"

namespace darc {

// G for the seed's 1D box of half-width r: 0 below -r, x above r, a parabola between.
inline double box_cdf_integral(double x, double r) {
  if (x <= -r) return 0.0;
  if (x >= r) return x;
  return (x + r) * (x + r) / (4.0 * r);
}

// G for a disc of radius r (disc_cdf).
inline double disc_cdf_integral(double x, double r) {
  if (x <= -r) return 0.0;
  if (x >= r) return x;
  const double s = x / r, q = std::sqrt(std::max(0.0, 1.0 - s * s));
  return r * ((s + 1.0) / 2.0 + (s * std::asin(s) + q - q * q * q / 3.0) / std::numbers::pi - 0.5);
}

// G for the sum of two centred uniforms of full widths a and b (trapezoid_cdf): truncated
// cubes, [R(x + h1) - R(x + h2) - R(x - h2) + R(x - h1)] / (6ab) with R(u) = max(u, 0)^3,
// h1 = (a + b)/2, h2 = |a - b|/2. A side much shorter than the other is a box.
inline double trapezoid_cdf_integral(double x, double a, double b) {
  if (a < b) std::swap(a, b);
  if (!(b > 1e-5 * a)) return box_cdf_integral(x, 0.5 * a);
  const double h1 = 0.5 * (a + b), h2 = 0.5 * (a - b);
  if (x <= -h1) return 0.0;
  if (x >= h1) return x;
  auto cube = [](double u) { return u > 0.0 ? u * u * u : 0.0; };
  return (cube(x + h1) - cube(x + h2) - cube(x - h2) + cube(x - h1)) / (6.0 * a * b);
}

// The band of half-width hw whose axis moves from signed distance d0 to d1, averaged over the
// motion, for a footprint whose G is `g` and whose size is `scale` (motions below 1e-7 of it
// are no motion: the static coverage at the middle).
template <class G, class Static>
float swept_band_coverage(double d0, double d1, double hw, double scale, G&& g, Static&& at_rest) {
  const double motion = d1 - d0;
  if (!(std::abs(motion) > 1e-7 * scale)) return at_rest(float(0.5 * (d0 + d1)));
  const double c = (g(d1 + hw) - g(d0 + hw) - g(d1 - hw) + g(d0 - hw)) / motion;
  return float(std::clamp(c, 0.0, 1.0));
}

inline float swept_coverage_box(double d0, double d1, double hw, double r) {
  return swept_band_coverage(
      d0, d1, hw, r, [r](double x) { return box_cdf_integral(x, r); },
      [&](float d) { return coverage_box(d, float(hw), float(r)); });
}

inline float swept_coverage_disc(double d0, double d1, double hw, double r) {
  return swept_band_coverage(
      d0, d1, hw, r, [r](double x) { return disc_cdf_integral(x, r); },
      [&](float d) { return coverage_disc(d, float(hw), float(r)); });
}

inline float swept_coverage_square(double d0, double d1, double hw, double a, double b) {
  return swept_band_coverage(
      d0, d1, hw, std::max(a, b), [a, b](double x) { return trapezoid_cdf_integral(x, a, b); },
      [&](float d) { return coverage_square(d, float(hw), float(a), float(b)); });
}

}  // namespace darc
