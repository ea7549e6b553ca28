// Helpers shared by the hard-case tests: parse a RIB string, build its one frame, render it in
// memory, and small measures over the result (defined in render_rib_util.cpp).
#pragma once

#include <functional>
#include <string>

#include "core/footprint/coverage.h"
#include "integrator/render_frame.h"

namespace darc::test {

// The stochastic reference: 64x64 jittered exact samples per pixel.
inline constexpr int kReferenceSamples = 64;

struct RenderedFrame {
  Image image;
  FrameStats stats;
};

struct AlphaComparison {
  bool all_valid = true;       // every alpha finite and in [0, 1]
  float max_pixel = 0;         // largest |alpha - reference| over the pixels
  double total_relative = 0;   // |sum alpha - sum reference| / sum reference
  double reference_total = 0;  // sum of the reference's alpha
};

// Colour against a reference, over R, G and B of every pixel.
struct RgbComparison {
  bool all_valid = true;  // every channel finite and not negative
  float max_pixel = 0;    // largest |channel - reference| over the pixels and channels
  double rms = 0;         // root mean square of the differences over the pixels and channels
};

// Both measures of the distance hider against the stochastic reference on one scene.
struct HiderComparison {
  AlphaComparison alpha;
  RgbComparison rgb;
};

RenderOptions single_thread(HiderKind hider);
RenderedFrame render_rib(const std::string& rib, const RenderOptions& options);
std::string orthographic_frame(int width, int height, int samples, const std::string& world);
std::string perspective_frame(int width, int height, int samples, float fov_degrees, const std::string& camera,
                              const std::string& world);
float alpha_at(const Image& image, int x, int y);
AlphaComparison compare_alpha(const Image& test, const Image& reference);
AlphaComparison distance_against_reference(const std::function<std::string(int samples)>& rib, CoverageModel model);
RgbComparison compare_rgb(const Image& test, const Image& reference);
// The distance hider (default settings, `distance_samples` x `distance_samples` footprints per
// pixel) against the stochastic hider with `reference_samples` x `reference_samples` samples.
// The reference's own validity is folded into all_valid.
HiderComparison distance_against_stochastic(const std::function<std::string(int samples)>& rib, int distance_samples,
                                            int reference_samples = kReferenceSamples);

}  // namespace darc::test
