// RI Points in both hiders: a point's coverage through the distance hider sums to its area,
// and it matches the stochastic hider's many exact samples; a row of overlapping points covers
// its union, not the sum of its discs; points cast shadows; renders are the same on 1 and 2
// threads.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "support/image_compare.h"
#include "support/pixel_measures.h"
#include "support/render.h"
#include "support/scenes_from_rib.h"

namespace darc {
namespace {

using test::build_scene;
using test::channel_sum;
using test::compare;
using test::ImageDifference;
using test::kAlpha;
using test::render_image;

constexpr double kPi = std::numbers::pi;
// The image: 64 x 64 pixels over the world square [-1, 1]^2 seen orthographically, so one pixel
// is kPixel world units and a footprint is exactly one pixel.
constexpr int kSide = 64;
constexpr double kPixel = 2.0 / kSide;

std::string scene_rib(const std::string& world) {
  return fmt::format(R"RIB(Format {0} {0} 1
PixelSamples 1 1
PixelFilter "box" 1 1
Projection "orthographic"
ScreenWindow -1 1 -1 1
Translate 0 0 5
WorldBegin
{1}
WorldEnd
)RIB",
                     kSide, world);
}

// The stochastic hider's reference: n x n exact samples per pixel.
Image render_reference(Scene scene, int n) {
  scene.output.pixel_samples[0] = scene.output.pixel_samples[1] = n;
  return render_image(scene, HiderKind::Stochastic);
}

// A point of radius r pixels (diameter 2r) at (x, y) in world units, white and matte.
std::string point(double x, double y, double r_pixels, double z = 0) {
  return fmt::format("Points \"P\" [{} {} {}] \"constantwidth\" {}", x, y, z, 2 * r_pixels * kPixel);
}

TEST(Points, CoverageSumsToTheDiscsAreaAndMatchesTheExactSamples) {
  const Scene scene = build_scene(scene_rib(R"(Surface "constant"
)" + point(0.013, -0.21, 0.3) + "\n" + point(-0.5, 0.4, 0.07) +
                                            "\n" + point(0.5, 0.5, 2.6)));
  ASSERT_EQ(scene.points.size(), 3u);
  const double area = kPi * (0.3 * 0.3 + 0.07 * 0.07 + 2.6 * 2.6);  // pixels
  const Image distance = render_image(scene, HiderKind::Distance);
  // The coverages of footprints tiling the image add up to the discs' area (exactly for the
  // square footprint; float rounding of the coverages aside).
  EXPECT_NEAR(channel_sum(distance, kAlpha), area, 1e-3 * area);
  const Image reference = render_reference(scene, 32);
  EXPECT_NEAR(channel_sum(reference, kAlpha), area, 0.02 * area) << "1024 exact samples per pixel";
  const ImageDifference d = compare(distance, reference, kAlpha);
  RecordProperty("alpha_rmse", std::to_string(d.rmse));
  RecordProperty("alpha_max", std::to_string(d.max));
  RecordProperty("area_error", std::to_string(channel_sum(distance, kAlpha) / area - 1));
  // Exact per pixel too (the disc's area in the pixel square): what is left is the reference's
  // sampling noise (measured: RMSE 1.4e-4, max 3.6e-3).
  EXPECT_LT(d.rmse, 2e-3) << "RMSE " << d.rmse << ", max " << d.max;
  EXPECT_LT(d.max, 2e-2) << "RMSE " << d.rmse << ", max " << d.max;
}

// A row of 60 points 0.1 pixel apart, each 0.5 pixel across, is a band with round ends: the
// masks let the overlapping discs count once, so the image covers the band's area, not 60 discs.
// (A band 0.5 pixel wide spans 4 rows of the 8 x 8 mask wherever it lies; narrower bands are
// measured in whole mask rows, to 1/8 pixel.)
TEST(Points, ARowOfOverlappingPointsCoversItsUnion) {
  const double r = 0.25, spacing = 0.1;
  const int n = 60;
  std::string P;
  for (int i = 0; i < n; ++i) P += fmt::format(" {} {} 0", (-3 + spacing * i) * kPixel, 0.37 * kPixel);
  const Scene scene = build_scene(
      scene_rib("Surface \"constant\"\nPoints \"P\" [" + P + "] \"constantwidth\" " + std::to_string(2 * r * kPixel)));
  const double union_area = (n - 1) * spacing * 2 * r + kPi * r * r, disc_sum = n * kPi * r * r;
  const Image distance = render_image(scene, HiderKind::Distance);
  const Image reference = render_reference(scene, 32);
  EXPECT_NEAR(channel_sum(reference, kAlpha), union_area, 0.03 * union_area);
  // Measured 2.8 % over: the masks place each disc's points to 1/8 pixel.
  EXPECT_NEAR(channel_sum(distance, kAlpha), union_area, 0.06 * union_area) << "the sum of the discs is " << disc_sum;
  const ImageDifference d = compare(distance, reference, kAlpha);
  RecordProperty("alpha_rmse", std::to_string(d.rmse));
  RecordProperty("alpha_max", std::to_string(d.max));
  RecordProperty("union_error", std::to_string(channel_sum(distance, kAlpha) / union_area - 1));
  EXPECT_LT(d.max, 0.1) << "RMSE " << d.rmse << ", max " << d.max;
  // The silhouette: the band (raster y 31.38 to 31.88, x 28.75 to 35.15) lies in pixel row 31,
  // columns 28 to 35; the footprints are the pixels, so nothing else is covered.
  for (int y = 0; y < kSide; ++y)
    for (int x = 0; x < kSide; ++x) {
      const bool in_band = y == kSide / 2 - 1 && x >= kSide / 2 - 4 && x <= kSide / 2 + 3;
      if (in_band) {
        EXPECT_GT(distance.at(x, y, 3), 0.0f) << "pixel " << x << ", " << y;
      } else {
        EXPECT_EQ(distance.at(x, y, 3), 0.0f) << "pixel " << x << ", " << y;
      }
    }
}

// A disc of radius R world units at height h over a plane, lit from 45 degrees: its shadow on
// the plane is an ellipse of semi-axes R and R sqrt 2, shifted by h along the light.
TEST(Points, PointsCastShadowsInBothHiders) {
  const double R = 0.25, h = 0.5;
  const Scene scene = build_scene(
      scene_rib(fmt::format(R"(LightSource "distantlight" 1 "from" [-1 0 -1] "to" [0 0 0] "string shadowname" "raytrace"
Surface "matte"
Polygon "P" [-1 -1 0  1 -1 0  1 1 0  -1 1 0]
Points "P" [-0.4 0 {}] "constantwidth" {})",
                            -h, 2 * R)));
  const double expected_area = kPi * R * R * std::sqrt(2.0) / (kPixel * kPixel);  // pixels
  for (HiderKind hider : {HiderKind::Distance, HiderKind::Stochastic}) {
    SCOPED_TRACE(hider == HiderKind::Distance ? "distance" : "stochastic");
    Scene s = scene;
    if (hider == HiderKind::Stochastic) s.output.pixel_samples[0] = s.output.pixel_samples[1] = 4;
    const Image image = render_image(s, hider);
    // Lit plane: the brightness where nothing is in the way (far right of the image).
    const float lit = image.at(kSide - 4, kSide / 2, 0);
    ASSERT_GT(lit, 0.1f);
    // The shadow's pixels, away from the disc itself (it hides x in [-0.65, -0.15] world units).
    double shadow = 0;
    for (int y = 0; y < kSide; ++y)
      for (int x = 0; x < kSide; ++x) {
        const double wx = -1 + (x + 0.5) * kPixel;
        if (std::abs(wx - (-0.4)) < R + kPixel) continue;
        shadow += 1.0 - std::clamp(double(image.at(x, y, 0)) / lit, 0.0, 1.0);
      }
    // The part of the ellipse (centre x = 0.1, semi-axis 0.354 along x) left of x = -0.15 - 1 px
    // is behind the disc: the visible fraction of the ellipse's area, computed.
    double visible = 0;
    const int steps = 4000;
    const double a = R * std::sqrt(2.0), cx = -0.4 + h;
    for (int i = 0; i < steps; ++i) {
      const double x = cx - a + (i + 0.5) * 2 * a / steps;
      if (std::abs(x - (-0.4)) < R + kPixel) continue;
      const double u = (x - cx) / a;
      visible += 2 * R * std::sqrt(std::max(0.0, 1 - u * u)) * (2 * a / steps);
    }
    visible /= kPixel * kPixel;
    RecordProperty(hider == HiderKind::Distance ? "distance_shadow_error" : "stochastic_shadow_error",
                   std::to_string(shadow / visible - 1));
    EXPECT_NEAR(shadow, visible, 0.05 * visible) << "the whole ellipse is " << expected_area << " pixels";
    EXPECT_LT(image.at(int((cx + 1) / kPixel), kSide / 2, 0), 0.05f * lit) << "the shadow's centre is dark";
  }
}

TEST(Points, SameImageOnOneAndTwoThreads) {
  std::string P, widths;
  for (int i = 0; i < 400; ++i) {
    const double x = std::fmod(i * 0.618034, 1.0) * 1.8 - 0.9, y = std::fmod(i * 0.414214, 1.0) * 1.8 - 0.9;
    P += fmt::format(" {} {} {}", x, y, std::fmod(i * 0.3, 1.0));
    widths += fmt::format(" {}", (0.2 + std::fmod(i * 0.7, 1.0)) * kPixel);
  }
  const Scene scene = build_scene(
      scene_rib("LightSource \"distantlight\" 1 \"from\" [1 1 -1] \"to\" [0 0 0] \"string shadowname\" \"raytrace\"\n"
                "Surface \"matte\"\nPoints \"P\" [" +
                P + "] \"width\" [" + widths + "]"));
  for (HiderKind hider : {HiderKind::Stochastic, HiderKind::Distance}) {
    const Image one = render_image(scene, hider, 1), two = render_image(scene, hider, 2);
    EXPECT_GT(channel_sum(one, kAlpha), 10.0);
    EXPECT_EQ(one.pixels, two.pixels);
  }
}

}  // namespace
}  // namespace darc
