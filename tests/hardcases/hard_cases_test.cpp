// The hard cases of curve-ray-tracing.md §6 for the distance-aware hider, each on a tiny scene
// rendered by both hiders: no NaN, alpha in [0, 1], and agreement with the stochastic 64x64
// reference within a tolerance stated (and explained) per case.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <random>
#include <sstream>
#include <string>

#include "support/hider_reference.h"
#include "support/pixel_measures.h"
#include "support/render.h"
#include "support/test_frames.h"

namespace darc::test {

namespace {

// Where a strand covers a pixel twice (where a loop crosses itself, a Catmull-Rom swing), the
// pieces of the strand combine through their coverage masks; what the masks place imprecisely
// (1/8 of the footprint) leaves such pixels off by up to this much (curve-ray-tracing.md §6
// cases 3 and 8). The rest of the image agrees to a few thousandths.
constexpr float kSelfOverlapPixelTolerance = 0.25f;
constexpr double kSelfOverlapTotalTolerance = 0.05;
// Bends tighter than the strand's width: every segment is cut at its joints (so that a strand
// shorter than the footprint covers only its length: docs/performance.md, grass), and the part
// of a segment that curves back across its joint's line is cut with it. Measured: 0.27 at one
// pixel inside the hairpin and one at the Catmull-Rom kink.
constexpr float kTightBendPixelTolerance = 0.3f;

AlphaComparison check_against_reference(const char* name, const std::function<std::string(int)>& rib) {
  AlphaComparison c = distance_against_reference(rib, CoverageModel::Square);
  std::printf("[ %s ] max pixel error %.4f, total alpha error %.4f (reference total %.3f)\n", name, c.max_pixel,
              c.total_relative, c.reference_total);
  EXPECT_TRUE(c.all_valid) << name << ": an alpha is NaN or outside [0, 1]";
  return c;
}

std::string linear_strand(const std::string& points, float width) {
  std::ostringstream s;
  s << "Curves \"linear\" [2] \"nonperiodic\" \"P\" [" << points << "] \"constantwidth\" [" << width << "]\n";
  return s.str();
}

// §6 case 1: a strand along the camera axis projects to a point. Both hiders see the ribbon
// (which faces the ray) as a disc of diameter `width` around the axis.
TEST(HardCases, RayParallelToTheStrand) {
  auto end_on = [](int samples) {
    return orthographic_frame(4, 4, samples, linear_strand("0.5 0.5 2  0.5 0.5 8", 0.5f));
  };
  AlphaComparison c = check_against_reference("end-on", end_on);
  EXPECT_LE(c.max_pixel, 0.03f);
  // Nearly parallel: a 0.05-pixel lean over 6 units of depth.
  auto nearly = [](int samples) {
    return orthographic_frame(4, 4, samples, linear_strand("0.5 0.5 2  0.55 0.5 8", 0.5f));
  };
  c = check_against_reference("nearly end-on", nearly);
  EXPECT_LE(c.max_pixel, 0.03f);
  // Perspective: a strand along the central ray, seen from its end.
  auto perspective = [](int samples) {
    return perspective_frame(3, 3, samples, 30, "", linear_strand("0 0 2  0 0 8", 0.05f));
  };
  // The reference sees nothing here (a line through the eye projects to a point, so every jittered
  // ray misses the ribbon); the distance hider's single ray is exactly on the axis and sees the
  // disc at the near end (0.016 of the pixel), as the orthographic reference does.
  c = check_against_reference("end-on perspective", perspective);
  EXPECT_LE(c.max_pixel, 0.02f);
}

// §6 case 2: strands 20x thinner than the footprint. Per pixel a thin strand is far below the
// reference's resolution, so compare the image's total alpha (the energy).
TEST(HardCases, VeryThinFarStrands) {
  constexpr int kStrands = 25;
  std::mt19937 rng(17);
  std::uniform_real_distribution<float> across(-30.0f, 30.0f), depth(190.0f, 210.0f), angle(0.0f, 6.2832f);
  std::ostringstream world;
  for (int i = 0; i < kStrands; ++i) {
    float x = across(rng), y = across(rng), z = depth(rng), a = angle(rng);
    float dx = 20 * std::cos(a), dy = 20 * std::sin(a);
    world << "Curves \"cubic\" [4] \"nonperiodic\" \"P\" [" << x - dx << " " << y - dy << " " << z << " " << x - dx / 3
          << " " << y << " " << z << " " << x + dx / 3 << " " << y + dy << " " << z + 5 << " " << x + dx << " "
          << y + dy / 2 << " " << z << "] \"constantwidth\" [0.3]\n";
  }
  // At depth 200 a pixel is 2 tan(10 deg) 200 / 12 = 5.9 units: width / footprint = 0.05.
  auto thin = [&](int samples) { return perspective_frame(12, 12, samples, 20, "", world.str()); };
  AlphaComparison c = check_against_reference("thin far strands", thin);
  EXPECT_GT(c.reference_total, 0.5);
  EXPECT_LE(c.total_relative, 0.03);
}

// §6 cases 3 and 4: a B-spline with a tripled start vertex (common in RIB) and a hairpin
// tighter than its width, and a Catmull-Rom kink.
TEST(HardCases, KinksAndCoincidentControlPoints) {
  auto hairpin = [](int samples) {
    return orthographic_frame(10, 10, samples,
                              "Basis \"b-spline\" 1 \"b-spline\" 1\n"
                              "Curves \"cubic\" [7] \"nonperiodic\" \"P\" [-4 -3 5  -4 -3 5  -4 -3 5  0 3.5 5  "
                              "0.6 -3 5  3 2 5  3 2 5] \"constantwidth\" [1.2]\n");
  };
  AlphaComparison c = check_against_reference("hairpin", hairpin);
  // Measured: 0.27 inside the bend, 0.3% in total.
  EXPECT_LE(c.max_pixel, kTightBendPixelTolerance);
  EXPECT_LE(c.total_relative, kSelfOverlapTotalTolerance);
  auto kink = [](int samples) {
    return orthographic_frame(10, 10, samples,
                              "Basis \"catmull-rom\" 1 \"catmull-rom\" 1\n"
                              "Curves \"cubic\" [6] \"nonperiodic\" \"P\" [-5 -4 5  -4 -3 5  0 3 5  0.2 -3 5  "
                              "4 2 5  5 3 5] \"constantwidth\" [0.4]\n");
  };
  c = check_against_reference("catmull-rom kink", kink);  // measured: 0.27 at the kink, 3.3% in total
  EXPECT_LE(c.max_pixel, kTightBendPixelTolerance);
  EXPECT_LE(c.total_relative, kSelfOverlapTotalTolerance);
}

// §6 case 4: repeated vertices make zero-length segments; the image must be the one of the
// strand without them, and a strand whose vertices all coincide shows nothing.
TEST(HardCases, ZeroLengthSegments) {
  RenderOptions options = single_thread(HiderKind::Distance);
  Image plain = render_rib(orthographic_frame(8, 4, 1, linear_strand("-6 0.3 5  6 0.3 5", 0.6f)), options).image;
  Image repeated = render_rib(orthographic_frame(8, 4, 1,
                                                 "Curves \"linear\" [5] \"nonperiodic\" \"P\" [-6 0.3 5  0 0.3 5  "
                                                 "0 0.3 5  0 0.3 5  6 0.3 5] \"constantwidth\" [0.6]\n"),
                              options)
                       .image;
  Image cubic = render_rib(orthographic_frame(8, 4, 1,
                                              "Curves \"cubic\" [4] \"nonperiodic\" \"P\" [-6 0.3 5  -6 0.3 5  "
                                              "6 0.3 5  6 0.3 5] \"constantwidth\" [0.6]\n"),
                           options)
                    .image;
  AlphaComparison c = compare_alpha(repeated, plain);
  EXPECT_TRUE(c.all_valid);
  EXPECT_LE(c.max_pixel, 1e-5f);
  c = compare_alpha(cubic, plain);  // zero end derivatives, same line
  EXPECT_TRUE(c.all_valid);
  EXPECT_LE(c.max_pixel, 1e-3f);  // a differently parametrised line: float rounding only
  EXPECT_NEAR(alpha_at(plain, 3, 1), 0.6f, 1e-5f);
  Image point = render_rib(orthographic_frame(8, 4, 1, linear_strand("0.5 0.5 5  0.5 0.5 5", 0.6f)), options).image;
  c = compare_alpha(point, point);
  EXPECT_TRUE(c.all_valid);
  EXPECT_EQ(c.reference_total, 0.0);
}

// §6 case 5: the same picture about 1e5 units from the origin (camera and strand moved). Floats
// there are 1/128 apart, so edges move by up to 0.004 pixel: alpha changes by about that much.
TEST(HardCases, CoordinatesNear1e5) {
  const std::string strand =
      "Curves \"cubic\" [4] \"nonperiodic\" \"P\" [-5.03 -2.17 5  -1.1 3.3 5  1.7 -3.1 6.2  5.3 2.9 5] "
      "\"constantwidth\" [0.7]\n";
  RenderOptions options = single_thread(HiderKind::Distance);
  Image near_origin = render_rib(orthographic_frame(10, 10, 1, strand), options).image;
  std::string moved_camera = orthographic_frame(10, 10, 1, "Translate 98765.4321 -123456.789 0\n" + strand);
  moved_camera.insert(moved_camera.find("WorldBegin"), "Translate -98765.4321 123456.789 0\n");
  Image moved = render_rib(moved_camera, options).image;
  AlphaComparison c = compare_alpha(moved, near_origin);
  std::printf("[ 1e5 ] max pixel difference %.4f\n", c.max_pixel);
  EXPECT_TRUE(c.all_valid);
  EXPECT_GT(c.reference_total, 3.0);
  EXPECT_LE(c.max_pixel, 0.02f);
  EXPECT_LE(c.total_relative, 0.005);
}

// §6 case 13: Embree's self-looping Bézier. Where the loop crosses itself one fragment per
// strand keeps the larger coverage, not the union.
TEST(HardCases, SelfLoopingCurve) {
  auto loop = [](int samples) {
    return perspective_frame(16, 16, samples, 50, "Translate -2 -2.2 9",
                             "Curves \"cubic\" [4] \"nonperiodic\" \"P\" [0 0 -2  8 4 -2  -4 4 -2  4 0 -3] "
                             "\"constantwidth\" [0.15]\n");
  };
  AlphaComparison c = check_against_reference("self loop", loop);
  EXPECT_GT(c.reference_total, 3.0);
  // Measured: 0.03 at the crossing pixel (the two passes combine through their masks); 0.7% in
  // total. (Keeping the larger coverage per strand instead gave 0.19.)
  EXPECT_LE(c.max_pixel, 0.1f);
  EXPECT_LE(c.total_relative, kSelfOverlapTotalTolerance);
}

// §6 case 15: Catmull-Rom end vertices far outside the curve they shape (they do not bound it).
TEST(HardCases, CatmullRomControlPointsOutsideTheCurve) {
  auto outside = [](int samples) {
    return orthographic_frame(10, 10, samples,
                              "Basis \"catmull-rom\" 1 \"catmull-rom\" 1\n"
                              "Curves \"cubic\" [4] \"nonperiodic\" \"P\" [-40 60 5  -3 0 5  3 0.5 5  40 -60 5] "
                              "\"constantwidth\" [0.8]\n");
  };
  AlphaComparison c = check_against_reference("catmull-rom outside", outside);
  EXPECT_GT(c.reference_total, 3.0);
  // The swing crosses itself: 0.24 at the crossing pixel, 0.04 elsewhere; 2.2% in total.
  EXPECT_LE(c.max_pixel, kSelfOverlapPixelTolerance);
  EXPECT_LE(c.total_relative, kSelfOverlapTotalTolerance);
}

// §6 case 16: a width that goes negative hides that part (RenderMan); zero width hides all.
TEST(HardCases, NegativeAndZeroWidths) {
  auto signed_width = [](int samples) {
    return orthographic_frame(10, 4, samples,
                              "Curves \"linear\" [3] \"nonperiodic\" \"P\" [-7 0.2 5  0 0.2 5  7 0.2 5] "
                              "\"width\" [-1 0.2 1.4]\n");
  };
  AlphaComparison c = check_against_reference("negative widths", signed_width);
  EXPECT_LE(c.max_pixel, 0.05f);
  EXPECT_LE(c.total_relative, 0.02);
  auto zero = [](int samples) { return orthographic_frame(6, 4, samples, linear_strand("-5 0 5  5 0 5", 0.0f)); };
  c = check_against_reference("zero width", zero);
  EXPECT_EQ(c.reference_total, 0.0);
  EXPECT_EQ(c.max_pixel, 0.0f);
}

// §6 case 11: pixels of 1e-9 units, far below the footprint floor (1e-7 of the scene): the
// distance hider becomes a hit test at pixel centres, which is exact for a band whose edges
// lie on pixel edges.
TEST(HardCases, FootprintTendingToZero) {
  auto tiny = [](int samples) {
    std::string rib = orthographic_frame(8, 8, samples, linear_strand("-5 0 5  5 0 5", 4e-9f));
    std::string window = "ScreenWindow -4 4 -4 4";
    rib.replace(rib.find(window), window.size(), "ScreenWindow -4e-9 4e-9 -4e-9 4e-9");
    return rib;
  };
  AlphaComparison c = check_against_reference("tiny pixels", tiny);
  EXPECT_NEAR(c.reference_total, 32.0, 1e-3);  // rows 2-5 covered
  EXPECT_LE(c.max_pixel, 1e-5f);
  // A pinhole camera with a strand just past the eye: the footprint there is nearly zero.
  auto at_the_eye = [](int samples) {
    return perspective_frame(6, 6, samples, 60, "", linear_strand("-1 0 1e-4  1 0 1e-4", 2e-5f));
  };
  c = check_against_reference("strand at the eye", at_the_eye);
  EXPECT_LE(c.max_pixel, 0.05f);
  EXPECT_LE(c.total_relative, 0.03);
}

}  // namespace
}  // namespace darc::test
