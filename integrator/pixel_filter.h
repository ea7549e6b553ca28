// Pixel reconstruction filters with RenderMan (RiPixelFilter) names and width conventions.
#pragma once

#include <optional>
#include <string_view>

namespace darc {

// A separable-or-radial reconstruction filter. Widths are RenderMan *full* widths in pixels: the
// support is the half-open box [-xwidth/2, xwidth/2) x [-ywidth/2, ywidth/2) around a pixel
// centre. Half-open so that, with a 1x1 box, a sample lying exactly on a pixel boundary counts
// for exactly one pixel (pixel i spans [i, i+1)). Weights are not normalised: the film divides by
// the weight sum, so only their ratios matter.
struct PixelFilter {
  enum class Type { Box, Triangle, Gaussian, CatmullRom, Sinc };
  Type type = Type::Gaussian;
  float xwidth = 2.0f;  // RI default: PixelFilter "gaussian" 2 2
  float ywidth = 2.0f;

  // Weight of a sample at offset (dx, dy) pixels from a pixel centre; 0 outside the support.
  // Always finite. Catmull-rom and sinc have negative lobes.
  float eval(float dx, float dy) const;
  float radius_x() const { return 0.5f * xwidth; }
  float radius_y() const { return 0.5f * ywidth; }
};

// Smallest accepted full width (pixels): narrower filters would miss samples entirely between
// pixel centres; RIB files that ask for less get this instead.
inline constexpr float kMinPixelFilterWidth = 1e-3f;
// Largest accepted full width (pixels): a sanity cap so a typo cannot make every sample splat
// over the whole image (PRMan users rarely go past 8).
inline constexpr float kMaxPixelFilterWidth = 64.0f;

// The filter named by RiPixelFilter ("box", "triangle", "gaussian", "catmull-rom", "sinc"; case
// sensitive like RIB). Widths are clamped to [kMinPixelFilterWidth, kMaxPixelFilterWidth]
// (non-finite widths become the RI default 2). Returns nullopt for an unknown name: the caller
// warns and keeps the default.
std::optional<PixelFilter> make_pixel_filter(std::string_view ri_name, float xwidth, float ywidth);

// The RI default filter, "gaussian" 2 2.
inline PixelFilter default_pixel_filter() { return PixelFilter{}; }

}  // namespace darc
