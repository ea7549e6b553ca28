// Patches and NURBS render as the exact surfaces they stand for, in both hiders: a bilinear patch
// ground as the Polygon with the same corners, a NURBS sphere as the Sphere primitive, and a
// rational bicubic quarter disk as a 1000-sided polygon of the exact arc (its sides are 3e-7 of
// the radius off the circle), to the same tolerances in both hiders but for one pixel of the
// ground's diagonal; and the same image on 1 and 2 threads.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "support/image_compare.h"
#include "support/pixel_measures.h"
#include "support/render.h"

namespace darc {
namespace {

using test::channel_sum;
using test::compare;
using test::ImageDifference;
using test::kAlpha;
using test::kRgba;
using test::render_image;

constexpr const char* kHeader = R"RIB(Format 64 48 1
PixelSamples 3 3
Projection "perspective" "fov" 40
Translate 0 -0.3 6
Rotate -25 1 0 0
WorldBegin
LightSource "distantlight" 1 "from" [1 3 -2] "to" [0 0 0]
LightSource "ambientlight" 2 "intensity" 0.15
Surface "matte"
)RIB";


TEST(PatchSurface, BilinearPatchGroundRendersAsItsPolygon) {
  // The patch's corners in RI patch order (0,0), (1,0), (0,1), (1,1) are the polygon's 0, 1, 3, 2.
  const std::string sphere =
      "AttributeBegin Color 0.8 0.5 0.3 Translate 0 0.7 0 Sphere 0.7 -0.7 0.7 360 AttributeEnd\n";
  const std::string polygon =
      std::string(kHeader) + sphere + "Polygon \"P\" [-2 0 -2  2 0 -2  2 0 2  -2 0 2]\nWorldEnd\n";
  const std::string patch =
      std::string(kHeader) + sphere + "Patch \"bilinear\" \"P\" [-2 0 -2  2 0 -2  -2 0 2  2 0 2]\nWorldEnd\n";
  for (HiderKind hider : {HiderKind::Stochastic, HiderKind::Distance}) {
    SCOPED_TRACE(to_string(hider));
    const Image a = render_image(polygon, hider), b = render_image(patch, hider);
    ASSERT_GT(channel_sum(a, kAlpha), 0.3 * 64 * 48) << "the ground fills much of the frame";
    const ImageDifference d = compare(a, b);
    EXPECT_LT(d.rmse, 2e-3);  // one plane: only the diagonal may differ
    // The distance hider's coverage of the diagonal's two sides sums to slightly under 1 at one
    // pixel (0.034 here); the stochastic hider's exact hits differ only by rounding.
    EXPECT_LT(d.max, hider == HiderKind::Distance ? 5e-2 : 2e-2);
  }
}

// Exporters write a surface as many Patch requests (the Aqsis vase: one per bicubic patch). The
// pieces of one material are one layer in the distance hider, so the patches meet as a mesh's
// triangles do: no seam where the background shows between them (before, each request was its
// own layer and the edge pixels composited two partial coverages, c1 + c2 (1 - c1) < 1: the
// vase's patch boundaries were dark lines).
TEST(PatchSurface, PatchesOfOneMaterialMeetWithoutASeam) {
  // One footprint a pixel, where a seam shows most (3x3 footprints average it away).
  std::string header = kHeader;
  header.replace(header.find("PixelSamples 3 3"), 16, "PixelSamples 1 1");
  const std::string one = header + "Patch \"bilinear\" \"P\" [-2 0 -2  2 0 -2  -2 0 2  2 0 2]\nWorldEnd\n";
  std::string four = header;
  for (double x : {-2.0, -0.3, 1.1})
    for (double z : {-2.0, 0.7}) {
      const double x1 = x == 1.1 ? 2.0 : (x == -2.0 ? -0.3 : 1.1), z1 = z == -2.0 ? 0.7 : 2.0;
      four += fmt::format("Patch \"bilinear\" \"P\" [{} 0 {}  {} 0 {}  {} 0 {}  {} 0 {}]\n", x, z, x1, z, x, z1, x1, z1);
    }
  four += "WorldEnd\n";
  const Image a = render_image(one, HiderKind::Distance), b = render_image(four, HiderKind::Distance);
  ASSERT_GT(channel_sum(a, kAlpha), 0.3 * 64 * 48) << "the ground fills much of the frame";
  const ImageDifference d = compare(a, b, kRgba);
  // Measured at 1x1 through the darc command: RMSE 0.0040 with a layer per request, 0.0013 with
  // one per material. What is left is the deficit where pieces of one plane meet at a point
  // inside a footprint, which a single patch's diagonal shows as well (the test above: 0.034).
  EXPECT_LT(d.rmse, 2e-3) << "a seam between the patches";
  EXPECT_LT(d.max, 5e-2);
}

// The unit sphere as a NuPatch of rational quadratic arcs (9 x 5 points, "Pw").
std::string nurbs_sphere() {
  const double h = std::sqrt(0.5);
  const double ax[] = {1, 1, 0, -1, -1, -1, 0, 1, 1}, ay[] = {0, 1, 1, 1, 0, -1, -1, -1, 0};
  const double aw[] = {1, h, 1, h, 1, h, 1, h, 1};
  const double px[] = {0, 1, 1, 1, 0}, pz[] = {-1, -1, 0, 1, 1}, pw[] = {1, h, 1, h, 1};
  std::string points;
  for (int j = 0; j < 5; ++j)
    for (int i = 0; i < 9; ++i) {
      const double w = aw[i] * pw[j];
      points += fmt::format(" {} {} {} {}", ax[i] * px[j] * w, ay[i] * px[j] * w, pz[j] * w, w);
    }
  return "NuPatch 9 3 [0 0 0 1 1 2 2 3 3 4 4 4] 0 4 5 3 [0 0 0 1 1 2 2 2] 0 2 \"Pw\" [" + points + "]\n";
}

TEST(PatchSurface, NurbsSphereHasTheSpheresSilhouetteAndShading) {
  const std::string place = "Color 0.3 0.6 0.8 Translate 0 0.5 0 Scale 1.5 1.5 1.5\n";
  const std::string exact = std::string(kHeader) + place + "Sphere 1 -1 1 360\nWorldEnd\n";
  const std::string nurbs = std::string(kHeader) + place + nurbs_sphere() + "WorldEnd\n";
  for (HiderKind hider : {HiderKind::Stochastic, HiderKind::Distance}) {
    SCOPED_TRACE(to_string(hider));
    const Image a = render_image(exact, hider), b = render_image(nurbs, hider);
    ASSERT_GT(channel_sum(a, kAlpha), 200) << "the sphere is in view";
    // Colour and alpha: a pixel that only a sliver of one of the two silhouettes reaches has a
    // depth in one image and none (the far plane) in the other; analytic coverage of the NURBS
    // triangles finds slivers the exact sphere's sub-rays miss.
    const ImageDifference alpha = compare(a, b, kAlpha), all = compare(a, b, kRgba);
    // Silhouette: the triangles are within 6e-4 of the radius (about 0.01 pixel here), so a sample
    // in that band is rare, and one sample weighs about 1/9 of a pixel.
    EXPECT_LT(alpha.rmse, 5e-3);
    EXPECT_LT(alpha.max, 0.15);
    EXPECT_NEAR(channel_sum(b, kAlpha), channel_sum(a, kAlpha), 2e-3 * channel_sum(a, kAlpha));
    // Shading: interpolated normals within 4 degrees of each other, so within 2 of the exact one.
    EXPECT_LT(all.rmse, 1e-2);
  }
}

TEST(PatchSurface, RationalBicubicQuarterDiskHasTheArcsSilhouette) {
  // A quarter disk of radius 1.8 about (-0.9, -0.9): the rational quadratic arc raised to a cubic
  // in u, scaled from the centre in v (its v = 0 edge collapses to the centre).
  constexpr double kRadius = 1.8, kCentre = -0.9;
  const double w = std::sqrt(0.5);
  const double hx[] = {1, 1.0 / 3 + 2 * w / 3, 2 * w / 3, 0}, hy[] = {0, 2 * w / 3, 1.0 / 3 + 2 * w / 3, 1};
  const double hw[] = {1, 1.0 / 3 + 2 * w / 3, 1.0 / 3 + 2 * w / 3, 1};
  std::string patch = "Patch \"bicubic\" \"Pw\" [";
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 4; ++i) {
      const double s = kRadius * j / 3;  // homogeneous: (centre w + s x_h, ...)
      patch += fmt::format(" {} {} 0 {}", kCentre * hw[i] + s * hx[i], kCentre * hw[i] + s * hy[i], hw[i]);
    }
  patch += "]\n";
  std::string polygon = fmt::format("Polygon \"P\" [{} {} 0", kCentre, kCentre);
  constexpr int kSides = 1000;
  for (int k = 0; k <= kSides; ++k) {
    const double a = M_PI / 2 * k / kSides;
    polygon += fmt::format(" {} {} 0", kCentre + kRadius * std::cos(a), kCentre + kRadius * std::sin(a));
  }
  polygon += "]\n";
  const std::string header = R"RIB(Format 64 64 1
PixelSamples 3 3
Projection "orthographic"
ScreenWindow -1 1 -1 1
Translate 0 0 5
WorldBegin
LightSource "ambientlight" 1 "intensity" 1
Surface "constant"
)RIB";
  for (HiderKind hider : {HiderKind::Stochastic, HiderKind::Distance}) {
    SCOPED_TRACE(to_string(hider));
    const Image a = render_image(header + polygon + "WorldEnd\n", hider),
                b = render_image(header + patch + "WorldEnd\n", hider);
    // A quarter of pi r^2 over the 2 x 2 screen window's 64 x 64 pixels.
    EXPECT_NEAR(channel_sum(a, kAlpha), M_PI * kRadius * kRadius / 4 / 4 * 64 * 64, 2);
    const ImageDifference alpha = compare(a, b, kAlpha);
    EXPECT_LT(alpha.rmse, 3e-3);
    EXPECT_LT(alpha.max, 0.15);  // a sample at most (about 1/9 of a pixel) on the other side
    EXPECT_NEAR(channel_sum(b, kAlpha), channel_sum(a, kAlpha), 2);
  }
}

TEST(PatchSurface, SameImageOnOneAndTwoThreads) {
  const std::string rib =
      std::string(kHeader) + "Basis \"b-spline\" 1 \"b-spline\" 1\n" +
      "PatchMesh \"bicubic\" 5 \"nonperiodic\" 4 \"nonperiodic\" \"P\" [" +
      "-2 0 -2 -1 0.3 -2 0 0 -2 1 0.4 -2 2 0 -2  -2 0.2 -0.7 -1 0 -0.7 0 0.5 -0.7 1 0 -0.7 2 0.1 -0.7 "
      "-2 0 0.7 -1 0.4 0.7 0 0 0.7 1 0.3 0.7 2 0 0.7  -2 0.3 2 -1 0 2 0 0.2 2 1 0 2 2 0.4 2]\n" +
      "Translate 0 0.8 0 Scale 0.6 0.6 0.6\n" + nurbs_sphere() + "WorldEnd\n";
  for (HiderKind hider : {HiderKind::Stochastic, HiderKind::Distance}) {
    SCOPED_TRACE(to_string(hider));
    const Image one = render_image(rib, hider, 1), two = render_image(rib, hider, 2);
    ASSERT_GT(channel_sum(one, kAlpha), 100);
    EXPECT_EQ(one.pixels, two.pixels);
  }
}

}  // namespace
}  // namespace darc
