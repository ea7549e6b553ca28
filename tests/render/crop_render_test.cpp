// A crop renders bitwise the same pixels as the same rectangle of the whole image: what lets a
// farm cut a frame into tiles (darc --crop, scripts/darc-slurm --tiles) and merge them into the
// image one machine renders. The samples of the pixels around the crop that the pixel filter
// reaches are rendered too, and every pixel's filter sums are added in the order the whole image
// adds them (integrator/film.h: Film::tiles). Both hiders, a filter wider than a pixel (the RI
// default gaussian 2 2, and catmull-rom 4 4 with negative lobes), 2x2 samples, a hair fan over a
// plastic sphere; crops on and off the render tiles' 32-pixel grid, at the image's edges, and the
// rows a farm cuts.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "support/render.h"

namespace darc {
namespace {

using test::render_image;

constexpr int kWidth = 72, kHeight = 44;
constexpr int kStrands = 24;

// A fan of hair strands in front of a plastic sphere, lit by a distant light; `options` go
// before WorldBegin (PixelFilter, CropWindow, DepthOfField, Shutter), `motion` moves the sphere.
std::string hair_and_sphere(const std::string& options, bool motion = false) {
  std::ostringstream s;
  s.precision(6);
  s << "Format " << kWidth << " " << kHeight << " 1\nPixelSamples 2 2\n"
    << options << "Projection \"perspective\" \"fov\" [40]\nTranslate 0 0 5\nWorldBegin\n"
    << "LightSource \"ambientlight\" 1 \"intensity\" [0.2]\n"
    << "LightSource \"distantlight\" 2 \"intensity\" [1.0] \"from\" [-1 1 -2] \"to\" [0 0 0]\n"
    << "AttributeBegin\nSurface \"plastic\"\nColor [0.2 0.4 0.9]\n";
  if (motion) s << "MotionBegin [0 1]\nTranslate -0.3 0 0\nTranslate 0.3 0 0\nMotionEnd\n";
  s << "Sphere 0.6 -0.6 0.6 360\nAttributeEnd\n"
    << "AttributeBegin\nSurface \"hair\"\nColor [0.9 0.6 0.3]\nCurves \"cubic\" [";
  for (int i = 0; i < kStrands; ++i) s << "4 ";
  s << "] \"nonperiodic\" \"P\" [";
  for (int i = 0; i < kStrands; ++i) {
    const double a = 2 * std::numbers::pi * i / kStrands;
    s << "0 0 0.8 " << 0.6 * std::cos(a) << " " << 0.6 * std::sin(a) << " 0.5 " << 1.2 * std::cos(a + 0.3) << " "
      << 1.2 * std::sin(a + 0.3) << " 0.2 " << 1.8 * std::cos(a + 0.5) << " " << 1.8 * std::sin(a + 0.5) << " 0 ";
  }
  s << "] \"constantwidth\" [0.03]\nAttributeEnd\nWorldEnd\n";
  return s.str();
}

std::string crop_window(double x0, double x1, double y0, double y1) {
  std::ostringstream s;
  s.precision(17);
  s << "CropWindow " << x0 << " " << x1 << " " << y0 << " " << y1 << "\n";
  return s.str();
}

// How many values of `crop` differ bitwise from the same pixels of `whole` (the data window, the
// channels and every float's bits compared; the first difference is reported).
int differences(const Image& crop, const Image& whole) {
  EXPECT_EQ(crop.channel_names, whole.channel_names);
  EXPECT_EQ(crop.width, whole.width);
  EXPECT_EQ(crop.height, whole.height);
  int differ = 0;
  const PixelRect& w = crop.data_window;
  for (int y = w.y0; y < w.y1; ++y)
    for (int x = w.x0; x < w.x1; ++x)
      for (int c = 0; c < crop.channels(); ++c) {
        const float a = crop.at(x, y, c), b = whole.at(x, y, c);
        if (std::memcmp(&a, &b, sizeof a) == 0) continue;
        if (differ++ == 0)
          ADD_FAILURE() << "pixel (" << x << ", " << y << ") channel " << crop.channel_names[size_t(c)] << ": crop "
                        << a << ", whole image " << b;
      }
  return differ;
}

struct Crop {
  double x0, x1, y0, y1;
  PixelRect pixels;  // what RI Spec's rule keeps of the 72x44 image
};

// Off the 32-pixel render tiles (across their corner), on them, and at each edge of the image
// (where the hair and the sphere are).
const std::vector<Crop> kCrops = {
    {0.3, 0.6, 0.4, 0.9, PixelRect{22, 18, 44, 40}},
    {31.5 / 72, 63.5 / 72, 0, 31.5 / 44, PixelRect{32, 0, 64, 32}},
    {0, 0.25, 0.5, 1, PixelRect{0, 22, 18, 44}},
    {0.7, 1, 0.3, 0.6, PixelRect{51, 14, 72, 27}},
};

void expect_crops_match(const std::string& filter, HiderKind hider, const std::vector<Crop>& crops = kCrops,
                        const std::string& extra = "", bool motion = false) {
  const Image whole = render_image(hair_and_sphere(filter + extra, motion), hider);
  ASSERT_EQ(whole.data_window, (PixelRect{0, 0, kWidth, kHeight}));
  for (const Crop& c : crops) {
    SCOPED_TRACE(crop_window(c.x0, c.x1, c.y0, c.y1));
    const Image crop =
        render_image(hair_and_sphere(filter + extra + crop_window(c.x0, c.x1, c.y0, c.y1), motion), hider);
    ASSERT_EQ(crop.data_window, c.pixels);
    EXPECT_EQ(differences(crop, whole), 0);
  }
}

TEST(CropRender, ACropIsBitwiseTheWholeImagesPixelsWithTheDefaultGaussian) {
  for (HiderKind hider : {HiderKind::Distance, HiderKind::Stochastic}) {
    SCOPED_TRACE(to_string(hider));
    expect_crops_match("PixelFilter \"gaussian\" 2 2\n", hider);
  }
}

TEST(CropRender, ACropIsBitwiseTheWholeImagesPixelsWithANegativeLobedFilterFourPixelsWide) {
  for (HiderKind hider : {HiderKind::Distance, HiderKind::Stochastic}) {
    SCOPED_TRACE(to_string(hider));
    expect_crops_match("PixelFilter \"catmull-rom\" 4 4\n", hider);
  }
}

// The lens and shutter strata are drawn per pixel too: a crop through depth of field and motion
// blur keeps them.
TEST(CropRender, ACropIsBitwiseTheWholeImagesPixelsThroughDepthOfFieldAndMotionBlur) {
  for (HiderKind hider : {HiderKind::Distance, HiderKind::Stochastic}) {
    SCOPED_TRACE(to_string(hider));
    expect_crops_match("PixelFilter \"gaussian\" 2 2\n", hider, {kCrops[0], kCrops[2]},
                       "DepthOfField 8 1 3\nShutter 0 1\n", true);
  }
}

// The rows a farm cuts a frame into (darc-slurm --tiles 3: CropWindow 0 1 k/3 (k+1)/3) cover the
// image once, and each is bitwise those rows of the whole image.
TEST(CropRender, TheRowsOfAFarmsTilesPartitionTheImageBitwise) {
  const std::string filter = "PixelFilter \"gaussian\" 2 2\n";
  const Image whole = render_image(hair_and_sphere(filter), HiderKind::Distance);
  constexpr int kRows = 3;
  int next_row = 0;
  for (int k = 0; k < kRows; ++k) {
    const Image row = render_image(
        hair_and_sphere(filter + crop_window(0, 1, double(k) / kRows, double(k + 1) / kRows)), HiderKind::Distance);
    EXPECT_EQ(row.data_window, (PixelRect{0, next_row, kWidth, row.data_window.y1})) << "tile " << k;
    next_row = row.data_window.y1;
    EXPECT_EQ(differences(row, whole), 0) << "tile " << k;
  }
  EXPECT_EQ(next_row, kHeight);
}

}  // namespace
}  // namespace darc
