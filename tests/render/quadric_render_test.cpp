// The quadrics rendered end to end in both hiders: the coverage of each pixel row equals the
// analytic width of the outline there, Sides 1 hides the back, Orientation "inside" turns the
// normal over (the lit side moves), and the image does not depend on the thread count.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <sstream>
#include <string>

#include "support/pixel_measures.h"
#include "support/render.h"
#include "support/scenes_from_rib.h"

namespace darc {
namespace {

using test::build_scene;
using test::render_image;

constexpr int kSize = 64;            // pixels per side
constexpr double kHalfWindow = 2.0;  // the screen window is [-2, 2]^2 world units
constexpr double kPixel = 2 * kHalfWindow / kSize;
// A row's coverage may differ from the analytic width by this much: each of the row's two
// outline crossings is resolved to a small fraction of a pixel by both hiders (the stochastic one
// with 4 x 4 samples, the distance one by footprint coverage).
constexpr double kRowTolerance = 0.35 * kPixel;

std::string orthographic_frame(const std::string& world, int samples = 4) {
  std::ostringstream s;
  s << "Format " << kSize << " " << kSize << " 1\nPixelSamples " << samples << " " << samples
    << "\nPixelFilter \"box\" 1 1\nProjection \"orthographic\"\nScreenWindow " << -kHalfWindow << " " << kHalfWindow
    << " " << -kHalfWindow << " " << kHalfWindow << "\nWorldBegin\n"
    << world << "WorldEnd\n";
  return s.str();
}

// Sum of a channel over pixel row j, in world units of width.
double row_coverage(const Image& image, int j, int channel) {
  double sum = 0;
  for (int i = 0; i < image.width; ++i) sum += image.at(i, j, channel);
  return sum * kPixel;
}

// The analytic outline width at world height y, averaged over the height of pixel row j.
double row_width(const std::function<double(double)>& width_at, int j) {
  const int n = 64;
  double top = kHalfWindow - j * kPixel, sum = 0;
  for (int k = 0; k < n; ++k) sum += width_at(top - (k + 0.5) * kPixel / n);
  return sum / n;
}

double clamped_sqrt(double x) { return std::sqrt(std::max(0.0, x)); }

struct Outline {
  const char* name;
  std::string rib;                         // at z = 5 in front of the camera, white, constant
  std::function<double(double)> width_at;  // x extent of the outline at world height y
};

// Each quadric seen so that its outline is a simple function of y: axes along y (Rotate -90
// about x takes object z to world y) or, for the disk and the torus, toward the camera.
std::vector<Outline> outlines() {
  const std::string up = "Translate 0 0 5 Rotate -90 1 0 0 ";
  return {
      {"Disk", "Translate 0 0 5 Disk 0 1.5 360\n", [](double y) { return 2 * clamped_sqrt(2.25 - y * y); }},
      {"Cylinder", up + "Cylinder 1 -1.5 1.5 360\n", [](double y) { return std::abs(y) < 1.5 ? 2.0 : 0.0; }},
      // Apex at y = 1, base at y = -1: half-width 1 - (y + 1) / 2.
      {"Cone", "Translate 0 -1 5 Rotate -90 1 0 0 Cone 2 1 360\n",
       [](double y) { return y > -1 && y < 1 ? 2 * (1 - (y + 1) / 2) : 0.0; }},
      // Vertex at y = -1, rim at y = 1: half-width sqrt((y + 1) / 2).
      {"Paraboloid", "Translate 0 -1 5 Rotate -90 1 0 0 Paraboloid 1 0 2 360\n",
       [](double y) { return y > -1 && y < 1 ? 2 * std::sqrt((y + 1) / 2) : 0.0; }},
      {"Hyperboloid", up + "Hyperboloid 1 -1 -1  1 1 1  360\n",
       [](double y) { return std::abs(y) < 1 ? 2 * std::sqrt(1 + y * y) : 0.0; }},
      {"Torus", "Translate 0 0 5 Torus 1 0.5 0 360 360\n",
       [](double y) { return 2 * clamped_sqrt(2.25 - y * y) - 2 * clamped_sqrt(0.25 - y * y); }},
  };
}

TEST(QuadricRender, RowCoverageIsTheAnalyticOutlineInBothHiders) {
  for (const Outline& o : outlines()) {
    SCOPED_TRACE(o.name);
    Scene scene = build_scene(orthographic_frame("Surface \"constant\"\n" + o.rib));
    ASSERT_EQ(scene.surfaces.quadrics.size(), 1u);
    Image distance = render_image(scene, HiderKind::Distance), stochastic = render_image(scene, HiderKind::Stochastic);
    const int alpha = distance.channel_index("A");
    ASSERT_GE(alpha, 0);
    double covered = 0;
    for (int j = 0; j < kSize; ++j) {
      SCOPED_TRACE(testing::Message() << "row " << j);
      const double expected = row_width(o.width_at, j);
      EXPECT_NEAR(row_coverage(distance, j, alpha), expected, kRowTolerance);
      EXPECT_NEAR(row_coverage(stochastic, j, alpha), expected, kRowTolerance);
      covered += expected;
    }
    EXPECT_GT(covered, 10 * kPixel) << "the outline is in the frame";
  }
}

TEST(QuadricRender, SidesOneHidesTheBack) {
  // The disk's normal +z points along the view direction: from the camera it shows its back.
  const std::string disk = "Translate 0 0 5 Disk 0 1 360\n";
  for (HiderKind hider : {HiderKind::Distance, HiderKind::Stochastic}) {
    auto coverage = [&](const std::string& attributes) {
      Scene scene = build_scene(orthographic_frame("Surface \"constant\"\n" + attributes + disk));
      Image image = render_image(scene, hider);
      return row_coverage(image, kSize / 2, image.channel_index("A"));
    };
    EXPECT_NEAR(coverage(""), 2.0, kRowTolerance) << "two-sided: seen from behind";
    EXPECT_EQ(coverage("Sides 1\n"), 0.0) << "one-sided: its back is hidden";
    EXPECT_NEAR(coverage("Sides 1\nReverseOrientation\n"), 2.0, kRowTolerance) << "turned over: its front";
  }
}

TEST(QuadricRender, OrientationInsideTurnsTheNormalOver) {
  // The far half of a cylinder (object y, the cut's side, turned to +z): a trough open toward the
  // camera, which sees only its inside. Matte, one-sided, lit from (1, 0, -1). With the default
  // orientation the normals point out of the trough, away from the camera: nothing is drawn.
  // Orientation "inside" turns them toward the axis: the trough appears, shaded with the inward
  // normal (-x, 0, -z) at the point (x, sqrt(1 - x^2)) each pixel sees: Kd (N.L) = (z - x) / sqrt 2.
  const std::string world =
      "LightSource \"distantlight\" 1 \"from\" [1 0 -1] \"to\" [0 0 0]\n"
      "Surface \"matte\" \"Ka\" [0]\nSides 1\n";
  const std::string trough = "Translate 0 0 5 Rotate 90 1 0 0 Cylinder 1 -1.5 1.5 180\n";
  for (HiderKind hider : {HiderKind::Distance, HiderKind::Stochastic}) {
    SCOPED_TRACE(to_string(hider));
    Image outside = render_image(build_scene(orthographic_frame(world + trough)), hider);
    Image inside = render_image(build_scene(orthographic_frame(world + "Orientation \"inside\"\n" + trough)), hider);
    const int alpha = outside.channel_index("A");
    EXPECT_EQ(row_coverage(outside, kSize / 2, alpha), 0.0);
    EXPECT_NEAR(row_coverage(inside, kSize / 2, alpha), 2.0, kRowTolerance);
    for (int i = 0; i < kSize; ++i) {
      const double x = -kHalfWindow + (i + 0.5) * kPixel;
      if (std::abs(x) > 1 - kPixel) continue;  // the rim's pixels are partly covered
      const double z = std::sqrt(1 - x * x);
      EXPECT_NEAR(inside.at(i, kSize / 2, 0), std::max(0.0, (z - x) / std::sqrt(2.0)), 0.03) << "x " << x;
    }
  }
}

TEST(QuadricRender, OneAndTwoThreadsGiveIdenticalImages) {
  // Several 32-pixel tiles, so two threads share the frame.
  std::string world = "LightSource \"distantlight\" 1 \"from\" [1 1 -1] \"to\" [0 0 0]\nSurface \"plastic\"\n";
  int k = 0;
  for (const Outline& o : outlines()) {
    world += "AttributeBegin\nTranslate " + std::to_string(-2.5 + (k % 3) * 2.5) + " " +
             std::to_string(k < 3 ? 1.2 : -1.2) + " 0\nScale 0.5 0.5 0.5\n" + o.rib + "AttributeEnd\n";
    ++k;
  }
  std::string rib = orthographic_frame(world, 2);
  rib.replace(rib.find("Format 64 64"), 12, "Format 96 64");
  rib.replace(rib.find("ScreenWindow -2 2"), 17, "ScreenWindow -3 3");
  Scene scene = build_scene(rib);
  ASSERT_EQ(scene.surfaces.quadrics.size(), 6u);
  for (HiderKind hider : {HiderKind::Distance, HiderKind::Stochastic}) {
    Image one = render_image(scene, hider, 1), two = render_image(scene, hider, 2);
    ASSERT_EQ(one.pixels.size(), two.pixels.size());
    EXPECT_TRUE(one.pixels == two.pixels) << to_string(hider);
    EXPECT_GT(test::channel_sum(one), 100.0) << "something was drawn";
  }
}

}  // namespace
}  // namespace darc
