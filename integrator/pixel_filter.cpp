#include "integrator/pixel_filter.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace darc {

namespace {

// RiGaussianFilter falloff: exp(-2 r^2) with r normalised so the support edge is r = 1,
// where the weight is exp(-2) ~ 0.135 and the spec truncates it (RI spec 3.2, Appendix E).
constexpr float kGaussianFalloff = 2.0f;
// The Catmull-Rom spline's own support, |t| < 2 (in its natural units). We scale it so that
// this support fills the filter width: for the common "catmull-rom" 4 4 that is one unit per
// pixel, the textbook kernel. (The RI spec's version is radial and never scales.)
constexpr float kCatmullRomSupport = 2.0f;
// Sinc values below this |x| use the limit sin(x)/x -> 1 (avoids 0/0).
constexpr float kSincSmallArgument = 1e-6f;

bool inside_half_open(float d, float radius) { return d >= -radius && d < radius; }

// The 1D Catmull-Rom cubic (B = 0, C = 1/2 in Mitchell-Netravali terms), 1 at 0, 0 at |t| >= 2.
// This is RiCatmullRomFilter divided by 2 and made separable.
float catmull_rom_1d(float t) {
  t = std::fabs(t);
  if (t >= kCatmullRomSupport) return 0.0f;
  const float t2 = t * t;
  if (t < 1.0f) return 1.5f * t * t2 - 2.5f * t2 + 1.0f;
  return -0.5f * t * t2 + 2.5f * t2 - 4.0f * t + 2.0f;
}

// sinc(pi x) in pixel units, windowed by cos(pi x / width), which falls to 0 exactly at the
// support edge |x| = width/2. The RI spec uses cos(pi x / (2 width)), which is still 0.7 at the
// edge and so truncates the kernel with a step; we prefer a continuous kernel.
float windowed_sinc_1d(float x, float width) {
  const float px = std::numbers::pi_v<float> * x;
  const float sinc = std::fabs(px) < kSincSmallArgument ? 1.0f : std::sin(px) / px;
  const float window = std::cos(std::numbers::pi_v<float> * x / width);
  return sinc * std::max(window, 0.0f);
}

float sanitise_width(float w) {
  if (!std::isfinite(w)) return 2.0f;  // the RI default width
  return std::clamp(w, kMinPixelFilterWidth, kMaxPixelFilterWidth);
}

}  // namespace

float PixelFilter::eval(float dx, float dy) const {
  const float rx = radius_x();
  const float ry = radius_y();
  if (!inside_half_open(dx, rx) || !inside_half_open(dy, ry)) return 0.0f;
  switch (type) {
    case Type::Box:
      return 1.0f;
    case Type::Triangle:
      // Separable tent reaching 0 at the support edge. (The RI spec's listing divides by the
      // half-width instead of normalising |x| by it; the shape intended is this one.)
      return (1.0f - std::fabs(dx) / rx) * (1.0f - std::fabs(dy) / ry);
    case Type::Gaussian: {
      const float x = dx / rx;
      const float y = dy / ry;
      return std::exp(-kGaussianFalloff * (x * x + y * y));
    }
    case Type::CatmullRom:
      return catmull_rom_1d(dx * kCatmullRomSupport / rx) * catmull_rom_1d(dy * kCatmullRomSupport / ry);
    case Type::Sinc:
      return windowed_sinc_1d(dx, xwidth) * windowed_sinc_1d(dy, ywidth);
  }
  return 0.0f;
}

std::optional<PixelFilter> make_pixel_filter(std::string_view ri_name, float xwidth, float ywidth) {
  PixelFilter f;
  if (ri_name == "box") {
    f.type = PixelFilter::Type::Box;
  } else if (ri_name == "triangle") {
    f.type = PixelFilter::Type::Triangle;
  } else if (ri_name == "gaussian") {
    f.type = PixelFilter::Type::Gaussian;
  } else if (ri_name == "catmull-rom") {
    f.type = PixelFilter::Type::CatmullRom;
  } else if (ri_name == "sinc") {
    f.type = PixelFilter::Type::Sinc;
  } else {
    return std::nullopt;
  }
  f.xwidth = sanitise_width(xwidth);
  f.ywidth = sanitise_width(ywidth);
  return f;
}

}  // namespace darc
