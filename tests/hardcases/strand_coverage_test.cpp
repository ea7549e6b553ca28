// Pixel coverage of an isolated straight strand under the distance-aware hider against the
// stochastic hider's 64x64 reference (box pixel filter), and thread-count determinism of both
// hiders on a small hair scene.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>
#include <sstream>
#include <string>

#include "support/hider_reference.h"
#include "support/render.h"
#include "support/test_frames.h"

namespace darc::test {

namespace {

// The reference's per-pixel standard error is below 0.4% for a straight edge (kReferenceSamples),
// so 2% is the distance hider's error, not the reference's.
constexpr float kSquarePixelTolerance = 0.02f;
// Alpha above 1 by less than this is float rounding: this test's bound, tighter than kAlphaRounding.
constexpr float kSingleStrandAlphaRounding = 1e-6f;
constexpr int kImageSize = 8;
// Half-length of the test strand: far beyond the image, so that its ends are not seen.
constexpr float kStrandHalfLength = 40.0f;

struct StrandCase {
  float width, angle_degrees, offset;  // width and offset in pixels
};

// A linear strand through (offset, offset * 0.6) at the given angle (world units are pixels).
std::string straight_strand(const StrandCase& c) {
  float a = c.angle_degrees * std::numbers::pi_v<float> / 180.0f;
  float dx = std::cos(a) * kStrandHalfLength, dy = std::sin(a) * kStrandHalfLength;
  float cx = c.offset, cy = 0.6f * c.offset;
  std::ostringstream s;
  s.precision(9);
  s << "Curves \"linear\" [2] \"nonperiodic\" \"P\" [" << cx - dx << " " << cy - dy << " 5 " << cx + dx << " "
    << cy + dy << " 5] \"constantwidth\" [" << c.width << "]\n";
  return s.str();
}

const StrandCase kCases[] = {
    {1.0f / 3.0f, 0, 0.5f}, {1.0f / 3.0f, 30, 0.23f}, {1.0f / 3.0f, 45, 0.0f}, {1.0f, 0, 0.1f},  {1.0f, 30, 0.5f},
    {1.0f, 45, 0.37f},      {2.0f, 0, 0.25f},         {2.0f, 30, 0.0f},        {2.0f, 45, 0.5f},
};

// Square is the default model and asserted; Box (the seed's) and Disc are printed beside it
// for the report (each case renders the reference once for all three).
TEST(StrandCoverage, SquareModelMatchesStochasticReferenceWithinTwoPercent) {
  const CoverageModel models[] = {CoverageModel::Square, CoverageModel::Box, CoverageModel::Disc};
  const char* names[] = {"square", "box", "disc"};
  float worst[3] = {0, 0, 0};
  for (const StrandCase& c : kCases) {
    std::string world = straight_strand(c);
    Image reference = render_rib(orthographic_frame(kImageSize, kImageSize, kReferenceSamples, world),
                                 single_thread(HiderKind::Stochastic))
                          .image;
    for (int m = 0; m < 3; ++m) {
      RenderOptions options = single_thread(HiderKind::Distance);
      options.distance.coverage = models[m];
      Image image = render_rib(orthographic_frame(kImageSize, kImageSize, 1, world), options).image;
      AlphaComparison e = compare_alpha(image, reference, kSingleStrandAlphaRounding);
      EXPECT_TRUE(e.all_valid) << "an alpha is NaN or outside [0, 1]";
      std::printf("[ %-6s ] width %.3f px, angle %2.0f deg, offset %.2f px: max pixel error %.4f, total %.4f\n",
                  names[m], c.width, c.angle_degrees, c.offset, e.max_pixel, e.total_relative);
      worst[m] = std::max(worst[m], e.max_pixel);
    }
  }
  std::printf("worst pixel error: square %.4f, box %.4f, disc %.4f\n", worst[0], worst[1], worst[2]);
  RecordProperty("box_worst_pixel_error", std::to_string(worst[1]));
  RecordProperty("disc_worst_pixel_error", std::to_string(worst[2]));
  EXPECT_LE(worst[0], kSquarePixelTolerance);
}

// The joints a strand runs straight through keep its area: a straight strand of width w and
// length L (ends and joints mid-pixel) sums to the same alpha as one segment or as three cut at
// two joints, at any angle, and to w L pixels when it runs along the pixel grid (where the product
// of the band's and the end line's coverage is exact; tilted, a square footprint's corner past
// the end makes it about 1 % low for this short strand at 30 degrees). The band past a cut end
// used to be measured from the end point instead of across the strand: the two pieces at each
// joint lost about 0.05 pixel of length together (3 % of this strand at 30 degrees).
TEST(StrandCoverage, JointsKeepTheStrandsArea) {
  constexpr int kSize = 16;
  constexpr double kWidth = 0.6, kLength = 5.37;
  auto alpha_sum = [&](double angle, int segments) {
    const double a = angle * std::numbers::pi / 180, dx = std::cos(a), dy = std::sin(a);
    std::ostringstream world;
    world.precision(9);
    world << "Curves \"linear\" [" << segments + 1 << "] \"nonperiodic\" \"P\" [";
    for (int k = 0; k <= segments; ++k) {
      const double s = k == 0 ? 0.0 : k == segments ? 1.0 : (k == 1 ? 0.29 : 0.71);  // uneven joints
      const double along = (s - 0.5) * kLength;
      world << 0.21 + along * dx << " " << -0.13 + along * dy << " 5 ";
    }
    world << "] \"constantwidth\" [" << kWidth << "]\n";
    const Image image =
        render_rib(orthographic_frame(kSize, kSize, 1, world.str()), single_thread(HiderKind::Distance)).image;
    double sum = 0;
    for (int y = 0; y < kSize; ++y)
      for (int x = 0; x < kSize; ++x) sum += image.at(x, y, 3);
    return sum;
  };
  const double area = kWidth * kLength;
  for (double angle : {0.0, 30.0, 73.0, 90.0}) {
    const double one = alpha_sum(angle, 1), three = alpha_sum(angle, 3);
    EXPECT_NEAR(three, one, 0.002 * area) << "angle " << angle << " degrees";
    if (angle == 0.0 || angle == 90.0) {
      EXPECT_NEAR(one, area, 0.002 * area) << "angle " << angle << " degrees";
      EXPECT_NEAR(three, area, 0.002 * area) << "angle " << angle << " degrees";
    }
  }
}

}  // namespace
}  // namespace darc::test
