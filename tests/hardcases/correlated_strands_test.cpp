// Hard case 8 of curve-ray-tracing.md §6: strands whose coverages are correlated. Scalar
// coverage composites two abutting 50 % strands to 75 % (not 100 %) and two coincident ones to
// 75 % (not 50 %); coverage masks composite them where they lie in the footprint.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <sstream>

#include "support/hider_reference.h"
#include "support/pixel_measures.h"
#include "support/render.h"
#include "support/test_frames.h"

namespace darc::test {
namespace {

// A vertical strand through x at depth z, spanning the whole (orthographic, 1 unit = 1 pixel)
// image, of the given width.
std::string vertical_strand(float x, float z, float width) {
  std::ostringstream s;
  s.precision(9);
  s << "Curves \"linear\" [2] \"nonperiodic\" \"P\" [" << x << " -20 " << z << " " << x << " 20 " << z
    << "] \"constantwidth\" [" << width << "]\n";
  return s.str();
}

float centre_alpha(const std::string& world, HiderKind hider, int samples, bool masks = true) {
  RenderOptions o = single_thread(hider);
  o.distance.coverage_masks = masks;
  RenderedFrame f = render_rib(orthographic_frame(1, 1, samples, world), o);
  return alpha_at(f.image, 0, 0);
}

TEST(CorrelatedStrands, AbuttingHalvesCoverThePixel) {
  // Two strands each covering one half of the pixel, at different depths.
  std::string world = vertical_strand(-0.25f, 5, 0.5f) + vertical_strand(0.25f, 6, 0.5f);
  float reference = centre_alpha(world, HiderKind::Stochastic, kReferenceSamples);
  EXPECT_NEAR(reference, 1.0f, 0.02f);
  EXPECT_NEAR(centre_alpha(world, HiderKind::Distance, 1), reference, 0.02f);
  EXPECT_NEAR(centre_alpha(world, HiderKind::Distance, 1, false), 0.75f, 0.01f) << "the scalar bias, for the record";
}

TEST(CorrelatedStrands, CoincidentStrandsCoverOnce) {
  std::string world = vertical_strand(0.1f, 5, 0.4f) + vertical_strand(0.1f, 6, 0.4f);
  float reference = centre_alpha(world, HiderKind::Stochastic, kReferenceSamples);
  EXPECT_NEAR(reference, 0.4f, 0.02f);
  EXPECT_NEAR(centre_alpha(world, HiderKind::Distance, 1), reference, 0.02f);
  EXPECT_NEAR(centre_alpha(world, HiderKind::Distance, 1, false), 1 - 0.6f * 0.6f, 0.01f);
}

TEST(CorrelatedStrands, ParallelBundleMatchesTheReferenceBetterThanScalar) {
  // Many thin parallel strands at random offsets and depths over a 16 x 4 image: the kind of
  // bundle a fur silhouette shows. Per-pixel alpha against 64x64 supersampling.
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> x(-8, 8), z(2, 9), w(0.1f, 0.6f);
  std::ostringstream world;
  for (int i = 0; i < 40; ++i) world << vertical_strand(x(rng), z(rng), w(rng));
  auto rib = [&](int samples) { return orthographic_frame(16, 4, samples, world.str()); };
  RenderedFrame ref = render_rib(rib(kReferenceSamples), single_thread(HiderKind::Stochastic));
  RenderOptions with_masks = single_thread(HiderKind::Distance), scalar = with_masks;
  scalar.distance.coverage_masks = false;
  AlphaComparison masked = compare_alpha(render_rib(rib(1), with_masks).image, ref.image);
  AlphaComparison plain = compare_alpha(render_rib(rib(1), scalar).image, ref.image);
  ASSERT_TRUE(masked.all_valid);
  // 8x8 mask points place each strand to 1/8 pixel, so per-pixel alpha is within about 1/16.
  EXPECT_LT(masked.max_pixel, 0.07f);
  EXPECT_LT(masked.total_relative, 0.02);
  EXPECT_LT(masked.max_pixel, plain.max_pixel);
}

}  // namespace
}  // namespace darc::test
