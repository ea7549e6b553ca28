#include "support/hider_reference.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>

#include "support/image_compare.h"
#include "support/pixel_measures.h"
#include "support/render.h"

namespace darc::test {

AlphaComparison compare_alpha(const Image& test, const Image& reference, float alpha_rounding) {
  AlphaComparison c;
  c.all_valid = all_within(test, kAlpha, 0.0f, 1.0f + alpha_rounding);
  c.max_pixel = float(compare(test, reference, kAlpha).max);
  const double sum_test = channel_sum(test, kAlpha);
  c.reference_total = channel_sum(reference, kAlpha);
  c.total_relative = c.reference_total > 0 ? std::abs(sum_test - c.reference_total) / c.reference_total : sum_test;
  return c;
}

RgbComparison compare_rgb(const Image& test, const Image& reference) {
  RgbComparison c;
  constexpr float kLargest = std::numeric_limits<float>::max();
  c.all_valid = all_within(test, kRgb, 0.0f, kLargest) && all_within(reference, kRgb, 0.0f, kLargest);
  const ImageDifference d = compare(test, reference, kRgb);
  c.max_pixel = float(d.max);
  c.rms = d.rmse;
  return c;
}

AlphaComparison distance_against_reference(const std::function<std::string(int samples)>& rib, CoverageModel model) {
  Image reference = render_rib(rib(kReferenceSamples), single_thread(HiderKind::Stochastic)).image;
  RenderOptions options = single_thread(HiderKind::Distance);
  options.distance.coverage = model;
  Image image = render_rib(rib(1), options).image;
  AlphaComparison c = compare_alpha(image, reference);
  if (std::getenv("DARC_TEST_DUMP_ALPHA")) {
    for (int y = 0; y < reference.height; ++y) {
      for (int x = 0; x < reference.width; ++x) std::fprintf(stderr, "%5.2f", alpha_at(image, x, y));
      std::fprintf(stderr, "   |");
      for (int x = 0; x < reference.width; ++x) std::fprintf(stderr, "%5.2f", alpha_at(reference, x, y));
      std::fprintf(stderr, "\n");
    }
  }
  // The reference must itself be valid: the stochastic hider meets the same hard case.
  c.all_valid = c.all_valid && compare_alpha(reference, reference).all_valid;
  return c;
}

HiderComparison distance_against_stochastic(const std::function<std::string(int samples)>& rib, int distance_samples,
                                            int reference_samples) {
  Image reference = render_rib(rib(reference_samples), single_thread(HiderKind::Stochastic)).image;
  Image image = render_rib(rib(distance_samples), single_thread(HiderKind::Distance)).image;
  HiderComparison c{compare_alpha(image, reference), compare_rgb(image, reference)};
  c.alpha.all_valid = c.alpha.all_valid && compare_alpha(reference, reference).all_valid;
  c.rgb.all_valid = c.rgb.all_valid && compare_rgb(reference, reference).all_valid;
  return c;
}

}  // namespace darc::test
