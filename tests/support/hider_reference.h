// The distance hider measured against the stochastic hider's reference (many jittered exact
// samples per pixel) on the same scene: alpha and colour differences, each with a check that
// every value is a valid one. For the hard-case tests of curve-ray-tracing.md §6.
#pragma once

#include <functional>
#include <string>

#include "core/footprint/coverage.h"
#include "integrator/film.h"

namespace darc::test {

// The stochastic reference: 64x64 jittered exact samples per pixel. Its per-pixel standard
// error is below 0.4 % for a straight edge.
inline constexpr int kReferenceSamples = 64;

// Alpha above 1 by less than this is float rounding of a sum of filter weights.
inline constexpr float kAlphaRounding = 1e-5f;

// Alpha against a reference.
struct AlphaComparison {
  bool all_valid = true;       // every alpha of the test image finite and in [0, 1]
  float max_pixel = 0;         // largest |alpha - reference| over the pixels
  double total_relative = 0;   // |sum alpha - sum reference| / sum reference
  double reference_total = 0;  // sum of the reference's alpha
};

// Colour against a reference, over R, G and B of every pixel.
struct RgbComparison {
  bool all_valid = true;  // every channel of both images finite and not negative
  float max_pixel = 0;    // largest |channel - reference| over the pixels and channels
  double rms = 0;         // root mean square of the differences over the pixels and channels
};

// Both measures of the distance hider against the stochastic reference on one scene.
struct HiderComparison {
  AlphaComparison alpha;
  RgbComparison rgb;
};

// `alpha_rounding`: how far above 1 an alpha may be and still count as valid.
AlphaComparison compare_alpha(const Image& test, const Image& reference, float alpha_rounding = kAlphaRounding);
RgbComparison compare_rgb(const Image& test, const Image& reference);

// `rib(samples)` is the scene with `samples` x `samples` pixel samples. The distance hider (one
// sample, coverage `model`) against the stochastic reference (kReferenceSamples), one thread
// each; the reference's own validity is folded into all_valid. With DARC_TEST_DUMP_ALPHA set,
// both alpha maps are printed side by side (a debugging aid).
AlphaComparison distance_against_reference(const std::function<std::string(int samples)>& rib, CoverageModel model);

// The distance hider (default settings, `distance_samples` x `distance_samples` footprints per
// pixel) against the stochastic hider with `reference_samples` x `reference_samples` samples.
// The reference's own validity is folded into all_valid.
HiderComparison distance_against_stochastic(const std::function<std::string(int samples)>& rib, int distance_samples,
                                            int reference_samples = kReferenceSamples);

}  // namespace darc::test
