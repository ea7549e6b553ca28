// DepthOfField end to end: a long opaque strand defocused far beyond its width keeps its alpha
// summed across a row (the area a lens conserves) and peaks near the thin lens's 4w/(pi c), with
// the default hider at one ray per pixel and with the stochastic hider's lens samples; a strand on
// the focal plane stays as sharp as through a pinhole; the image is the same for any thread
// count.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <sstream>
#include <string>

#include "support/render.h"

namespace darc {
namespace {

using test::render_image;

constexpr int kWidth = 64, kHeight = 32;
constexpr double kFov = 30;
// A pixel's size on the tangent plane z = 1 (the fov spans the shorter, vertical axis).
const double kPixel = 2 * std::tan(kFov * std::numbers::pi / 360) / kHeight;
constexpr double kStrandDepth = 10;
constexpr double kWidthPixels = 0.5;

// A vertical opaque strand kWidthPixels wide at camera depth 10, in the middle column, through a
// lens of focal length 1 focused at `focus` whose circle of confusion at the strand is `coc`
// pixels across (c = 2r |1/z - 1/F| / pixel); coc 0 is a pinhole.
std::string strand_scene(double coc, double focus, int samples = 1) {
  std::ostringstream s;
  s.precision(9);
  s << "Format " << kWidth << " " << kHeight << " 1\nPixelSamples " << samples << " " << samples
    << "\nPixelFilter \"box\" 1 1\n"
    << "Projection \"perspective\" \"fov\" [" << kFov << "]\n";
  if (coc > 0) {
    const double radius = coc * kPixel / (2 * std::abs(1 / kStrandDepth - 1 / focus));
    s << "DepthOfField " << 1 / (2 * radius) << " 1 " << focus << "\n";
  }
  // Half a pixel off the column's centre line, so that the pinhole strand lies in one column.
  const double x = 0.5 * kPixel * kStrandDepth;
  s << "WorldBegin\nSurface \"constant\"\nCurves \"linear\" [2] \"nonperiodic\" \"P\" [" << x << " -8 "
    << kStrandDepth << "  " << x << " 8 " << kStrandDepth << "] \"constantwidth\" ["
    << kWidthPixels * kPixel * kStrandDepth << "]\nWorldEnd\n";
  return s.str();
}

struct RowProfile {
  double sum = 0;   // alpha summed across a row, averaged over the middle rows
  double peak = 0;  // the largest of the rows' mean alphas
};

RowProfile profile(const Image& image) {
  RowProfile p;
  const int y0 = kHeight / 4, y1 = 3 * kHeight / 4;
  for (int x = 0; x < kWidth; ++x) {
    double column = 0;
    for (int y = y0; y < y1; ++y) column += image.at(x, y, 3);
    column /= (y1 - y0);
    p.sum += column;
    p.peak = std::max(p.peak, column);
  }
  return p;
}

// The thin lens's peak for a box pixel (../shared/docs/motion-and-programs.md A3.7).
double thin_lens_peak(double w, double c) { return 4 * w / (std::numbers::pi * c) * (1 - (w * w + 1) / (6 * c * c)); }

TEST(DepthOfFieldRender, ADefocusedStrandKeepsItsRowSumAndPeaksNearTheThinLens) {
  for (double focus : {5.0, 20.0}) {  // the strand behind and in front of the focal plane
    const double coc = 16;
    const RowProfile d = profile(render_image(strand_scene(coc, focus), HiderKind::Distance));
    // One ray per pixel: the footprint carries the lens (issue 20's targets: 5 % and 15 %).
    EXPECT_NEAR(d.sum, kWidthPixels, 0.05 * kWidthPixels) << "focus " << focus;
    EXPECT_NEAR(d.peak, thin_lens_peak(kWidthPixels, coc), 0.15 * thin_lens_peak(kWidthPixels, coc))
        << "focus " << focus;
    EXPECT_LT(d.peak, 2 * thin_lens_peak(kWidthPixels, coc)) << "blurred, not sharp";
  }
}

TEST(DepthOfFieldRender, TheStochasticHiderSamplesTheLens) {
  const double coc = 16;
  const RowProfile s = profile(render_image(strand_scene(coc, 5, 8), HiderKind::Stochastic));
  // 64 lens samples a pixel, 16 rows: the mean is within a few percent.
  EXPECT_NEAR(s.sum, kWidthPixels, 0.05 * kWidthPixels);
  EXPECT_NEAR(s.peak, thin_lens_peak(kWidthPixels, coc), 0.25 * thin_lens_peak(kWidthPixels, coc));
}

TEST(DepthOfFieldRender, AStrandOnTheFocalPlaneIsAsSharpAsThroughAPinhole) {
  const double coc_elsewhere = 16;  // the same lens, now focused on the strand
  for (HiderKind hider : {HiderKind::Distance, HiderKind::Stochastic}) {
    // The stochastic hider's 4x4 strata keep its estimate of the sharp strand within a few percent.
    const int samples = hider == HiderKind::Stochastic ? 4 : 1;
    std::string focused = strand_scene(coc_elsewhere, 5, samples);
    const std::string from = " 1 5\n", to = " 1 10\n";
    focused.replace(focused.find(from), from.size(), to);
    const RowProfile lens = profile(render_image(focused, hider));
    const RowProfile pinhole = profile(render_image(strand_scene(0, 5, samples), hider));
    EXPECT_NEAR(pinhole.peak, kWidthPixels, 0.1 * kWidthPixels) << to_string(hider);
    EXPECT_NEAR(lens.peak, pinhole.peak, 0.1 * pinhole.peak) << to_string(hider);
    EXPECT_NEAR(lens.sum, kWidthPixels, 0.05 * kWidthPixels) << to_string(hider);
  }
}

// Strands standing on a ground seen through a lens, low over it: the ground's depth changes
// across a footprint by far more than across a pixel, so a strand's root is in front of the
// ground in part of the footprint and behind it in the rest. The distance hider keeps the
// strands' light (red) within 2 % of the stochastic hider's lens samples. Measured: 1.1 % low;
// 3.0 % low when the ground was one fragment at its centre's depth and strands behind that
// depth were culled.
TEST(DepthOfFieldRender, StrandsOnAGroundKeepTheirLightThroughALens) {
  const std::string scene =
      "Format 64 48 1\nPixelSamples 1 1\nPixelFilter \"box\" 1 1\n"
      "Projection \"perspective\" \"fov\" [30]\nDepthOfField 1.4 0.2 12\n"
      "Rotate -3 1 0 0\nTranslate 0 -0.15 0\nWorldBegin\nSurface \"constant\"\n"
      "AttributeBegin\nColor [0 1 0]\nPolygon \"P\" [-20 0 -5  20 0 -5  20 0 60  -20 0 60]\nAttributeEnd\n"
      "Color [1 0 0]\nCurves \"linear\" [2 2 2] \"nonperiodic\" \"P\" [-0.4 0 3 -0.4 0.3 3  0 0 3 0 0.3 3  "
      "0.4 0 3 0.4 0.3 3] \"constantwidth\" [0.01]\nWorldEnd\n";
  auto red = [](const Image& image) {
    double sum = 0;
    for (int y = 0; y < image.height; ++y)
      for (int x = 0; x < image.width; ++x) sum += image.at(x, y, 0);
    return sum;
  };
  std::string reference_scene = scene;
  reference_scene.replace(reference_scene.find("PixelSamples 1 1"), 16, "PixelSamples 16 16");
  const double reference = red(render_image(reference_scene, HiderKind::Stochastic, 2));
  const double distance = red(render_image(scene, HiderKind::Distance));
  ASSERT_GT(reference, 1.0) << "the strands are in the picture";
  EXPECT_NEAR(distance, reference, 0.02 * reference);
}

TEST(DepthOfFieldRender, TheImageIsTheSameForAnyThreadCount) {
  std::string scene = strand_scene(6, 5, 2);
  scene.insert(scene.find("WorldEnd"),
               "Surface \"matte\"\nLightSource \"ambientlight\" 1 \"intensity\" [1]\n"
               "Polygon \"P\" [-3 -1 12  3 -1 12  3 -1 4  -3 -1 4]\nTranslate 1 0 7\nSphere 0.4 -0.4 0.4 360\n");
  for (HiderKind hider : {HiderKind::Distance, HiderKind::Stochastic}) {
    const Image a = render_image(scene, hider, 1), b = render_image(scene, hider, 2);
    ASSERT_EQ(a.pixels.size(), b.pixels.size());
    EXPECT_EQ(a.pixels, b.pixels) << to_string(hider);
  }
}

}  // namespace
}  // namespace darc
