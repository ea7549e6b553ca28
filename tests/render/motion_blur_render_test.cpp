// Motion blur end to end: a vertical opaque strand w pixels wide moving L pixels across the
// shutter leaves alpha w/L on every pixel well inside its sweep and w summed across a row (the
// area the shutter conserves), with the default hider at one ray per pixel (its rays sweep the
// shutter: the time-swept coverage in closed form) and with the stochastic hider's jittered
// times; a transform block, a deformation block and a turning transform all move it; a shutter
// that opens and closes gradually (Camera "shutteropening") weights the middle of the sweep; the
// image is the same for any thread count.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <string>

#include "support/render.h"

namespace darc {
namespace {

using test::render_image;

constexpr int kWidth = 64, kHeight = 16;
constexpr double kStrandWidth = 0.5;  // pixels
constexpr double kSweep = 20;         // pixels across the shutter

// An orthographic camera with one world unit per pixel; the strand runs down the image at x0 at
// shutter open, `motion` says how it moves to x0 + kSweep.
std::string strand_scene(const std::string& motion, int samples = 1) {
  std::ostringstream s;
  s << "Format " << kWidth << " " << kHeight << " 1\nPixelSamples " << samples << " " << samples
    << "\nPixelFilter \"box\" 1 1\nProjection \"orthographic\"\nScreenWindow " << -kWidth / 2 << " " << kWidth / 2
    << " " << -kHeight / 2 << " " << kHeight / 2 << "\nShutter 0 1\nWorldBegin\nSurface \"constant\"\n"
    << motion << "\nWorldEnd\n";
  return s.str();
}

std::string strand(double x) {
  std::ostringstream s;
  s << "Curves \"linear\" [2] \"nonperiodic\" \"P\" [" << x << " -20 5  " << x << " 20 5] \"constantwidth\" ["
    << kStrandWidth << "]";
  return s.str();
}

// Pixel column i covers x in [i - 32, i - 31]; the strand starts at x = -10.25 and ends at 9.75.
const std::string kTranslateBlock = "MotionBegin [0 1]\nTranslate 0 0 0\nTranslate 20 0 0\nMotionEnd\n" + strand(-10.25);
const std::string kDeformationBlock = "MotionBegin [0 1]\n" + strand(-10.25) + "\n" + strand(9.75) + "\nMotionEnd";

struct Row {
  double sum = 0;
  double inside_min = 1e9, inside_max = -1e9;  // over the pixels well inside the sweep
};

Row row_alpha(const Image& image) {
  Row r;
  for (int x = 0; x < kWidth; ++x) {
    double column = 0;
    for (int y = 4; y < kHeight - 4; ++y) column += image.at(x, y, 3);
    column /= (kHeight - 8);
    r.sum += column;
    // Pixels whose whole width lies more than the strand's half-width inside the sweep.
    const double left = x - 32.0, right = left + 1;
    if (left >= -10.25 + 0.25 && right <= 9.75 - 0.25) {
      r.inside_min = std::min(r.inside_min, column);
      r.inside_max = std::max(r.inside_max, column);
    }
  }
  return r;
}

TEST(MotionBlurRender, AMovingStrandLeavesItsWidthOverTheSweepAtOneRayPerPixel) {
  const double plateau = kStrandWidth / kSweep;
  for (const std::string& motion : {kTranslateBlock, kDeformationBlock}) {
    const Row r = row_alpha(render_image(strand_scene(motion), HiderKind::Distance));
    EXPECT_NEAR(r.inside_min, plateau, 0.1 * plateau);
    EXPECT_NEAR(r.inside_max, plateau, 0.1 * plateau);
    EXPECT_NEAR(r.sum, kStrandWidth, 0.02 * kStrandWidth);
  }
}

TEST(MotionBlurRender, TheStochasticHiderSamplesTheShutter) {
  const Row r = row_alpha(render_image(strand_scene(kTranslateBlock, 8), HiderKind::Stochastic));
  EXPECT_NEAR(r.sum, kStrandWidth, 0.05 * kStrandWidth);
  // 64 times per pixel and 8 rows: the plateau within the noise of 512 samples of 1/40.
  EXPECT_GT(r.inside_min, 0.0);
  EXPECT_LT(r.inside_max, 3 * kStrandWidth / kSweep);
}

TEST(MotionBlurRender, AStillStrandAndAClosedShutterStaySharp) {
  std::string closed = strand_scene(kTranslateBlock);
  closed.replace(closed.find("Shutter 0 1"), 11, "Shutter 0 0");
  std::string closed_8x8 = closed;
  closed_8x8.replace(closed_8x8.find("PixelSamples 1 1"), 16, "PixelSamples 8 8");
  for (HiderKind hider : {HiderKind::Distance, HiderKind::Stochastic}) {
    const Row r = row_alpha(render_image(hider == HiderKind::Distance ? closed : closed_8x8, hider));
    EXPECT_NEAR(r.sum, kStrandWidth, 0.05 * kStrandWidth) << to_string(hider);
    EXPECT_LT(r.inside_min, 1e-6) << "at shutter open only: " << to_string(hider);
  }
}

TEST(MotionBlurRender, ATurningTransformSweepsAnArc) {
  // The strand turns 90 degrees about the image centre's axis (z) during the shutter: a short
  // radial strand from radius 4 to 6 sweeps a quarter annulus (turned rigidly; its keys' chords
  // would cut the corner down to radius 2.8), conserving its area.
  const std::string turning =
      "MotionBegin [0 1]\nRotate 0 0 0 1\nRotate 90 0 0 1\nMotionEnd\n"
      "Curves \"linear\" [2] \"nonperiodic\" \"P\" [4 0 5  6 0 5] \"constantwidth\" [0.5]";
  for (HiderKind hider : {HiderKind::Distance, HiderKind::Stochastic}) {
    const bool distance = hider == HiderKind::Distance;
    const Image image = render_image(strand_scene(turning, distance ? 1 : 16), hider);
    double sum = 0;
    for (int y = 0; y < kHeight; ++y)
      for (int x = 0; x < kWidth; ++x) {
        sum += image.at(x, y, 3);
        // Pixel (x, y) has its centre at world (x - 31.5, 7.5 - y).
        const double r = std::hypot(x - 31.5, 7.5 - y);
        if (r < 3.0 || r > 7.0) {
          EXPECT_EQ(image.at(x, y, 3), 0.0f) << x << " " << y << " " << to_string(hider);
        }
      }
    // A rigid turn covers the strand's area (2 x 0.5 pixels) at every time (the stochastic hider's
    // 256 samples per pixel hit it about 256 times in all).
    EXPECT_NEAR(sum, 1.0, distance ? 0.03 : 0.2) << to_string(hider);
  }
}

TEST(MotionBlurRender, StrandsMovingTogetherAddUpAsTheyCoverThePixelAtDifferentTimes) {
  // A comb of parallel strands 1 pixel apart (0.3 wide, at slightly different depths) moving 10
  // pixels: every pixel inside is covered 30 % of the time, by one strand after another.
  // Composited as independent, ten coverages of 0.03 would give 1 - 0.97^10 = 0.26; the mask
  // points stand for times (mask_point_time), so strands that pass at different times take
  // different points and add up.
  std::ostringstream comb;
  comb << "MotionBegin [0 1]\nTranslate 0 0 0\nTranslate 10 0 0\nMotionEnd\nCurves \"linear\" [";
  for (int i = -40; i < 30; ++i) comb << " 2";
  comb << "] \"nonperiodic\" \"P\" [";
  for (int i = -40; i < 30; ++i) {
    const double x = i + 0.37, z = 5 + 0.013 * ((i + 40) % 7);
    comb << x << " -20 " << z << "  " << x << " 20 " << z << "  ";
  }
  comb << "] \"constantwidth\" [0.3]";
  const Image image = render_image(strand_scene(comb.str()), HiderKind::Distance);
  double sum = 0, lowest = 1;
  int n = 0;
  for (int y = 4; y < kHeight - 4; ++y)
    for (int x = 10; x < 50; ++x) {
      sum += image.at(x, y, 3);
      lowest = std::min(lowest, double(image.at(x, y, 3)));
      ++n;
    }
  EXPECT_NEAR(sum / n, 0.3, 0.01);
  EXPECT_GT(lowest, 0.25);
}

TEST(MotionBlurRender, TheImageIsTheSameForAnyThreadCount) {
  for (HiderKind hider : {HiderKind::Distance, HiderKind::Stochastic}) {
    const std::string scene = strand_scene(kDeformationBlock, 2);
    const Image a = render_image(scene, hider, 1), b = render_image(scene, hider, 2);
    EXPECT_EQ(a.pixels, b.pixels) << to_string(hider);
  }
}

TEST(MotionBlurRender, AShutterThatOpensGraduallyWeightsTheMiddleOfTheSweep) {
  // shutteropening [0.5 0.5]: the shutter opens until mid-shutter and closes at once after, a
  // triangle of weight 2 at the middle: the strand leaves twice the box shutter's alpha where it
  // passes at mid-shutter and little near the ends, and its width summed across a row.
  std::string triangle = strand_scene(kTranslateBlock);
  triangle.replace(triangle.find("Shutter 0 1"), 11, "Shutter 0 1\nCamera \"main\" \"float[2] shutteropening\" [0.5 0.5]");
  std::string triangle_16x16 = triangle;
  triangle_16x16.replace(triangle_16x16.find("PixelSamples 1 1"), 16, "PixelSamples 16 16");
  for (HiderKind hider : {HiderKind::Distance, HiderKind::Stochastic}) {
    const Image image = render_image(hider == HiderKind::Distance ? triangle : triangle_16x16, hider);
    const Row r = row_alpha(image);
    EXPECT_NEAR(r.sum, kStrandWidth, 0.03 * kStrandWidth) << to_string(hider);
    // Columns 32 and 31 hold the strand at mid-shutter (x = -0.25); columns 23 and 40, a
    // little more than 0.4 of the shutter away from it, at under a fifth of the peak weight.
    auto column = [&](int x) {
      double c = 0;
      for (int y = 4; y < kHeight - 4; ++y) c += image.at(x, y, 3);
      return c / (kHeight - 8);
    };
    const double box = kStrandWidth / kSweep;
    const double middle = 0.5 * (column(31) + column(32));
    // The distance hider's four stretches of equal weight make the triangle a staircase whose
    // middle steps weigh 1.71; the stochastic hider samples it (256 times per pixel, 8 rows:
    // about 1.87 expected, with a standard deviation of about 0.14).
    EXPECT_GT(middle, 1.5 * box) << to_string(hider);
    EXPECT_LT(middle, 2.3 * box) << to_string(hider);
    EXPECT_LT(0.5 * (column(23) + column(40)), 0.8 * box) << to_string(hider);
  }
}

}  // namespace
}  // namespace darc
