// crop_pixels: the pixel rectangle of a CropWindow (or darc --crop), RI Spec 3.2's rule; and the
// promise scripts/darc-slurm --tiles relies on: the rows [k/N, (k+1)/N] of an image of more than
// N pixel rows, cut by that rule, cover every pixel row exactly once, and each row keeps a pixel
// row (scripts/darc_slurm/tiles.py says why).
#include <gtest/gtest.h>

#include <charconv>
#include <string>
#include <vector>

#include "integrator/render_frame.h"

namespace darc {
namespace {

// The largest side Format or --res accepts (core/scene/builder/scene_builder_options.cpp).
constexpr int kMaxResolution = 16384;
// The most rows checked per image: more than a farm gives one frame.
constexpr int kMaxRows = 64;

PixelRect crop_of(int xres, int yres, double x0, double x1, double y0, double y1) {
  OutputSettings out;
  out.xres = xres;
  out.yres = yres;
  out.crop[0] = x0, out.crop[1] = x1, out.crop[2] = y0, out.crop[3] = y1;
  return crop_pixels(out);
}

// darc-slurm writes k/N as Python's repr(), the shortest text that reads back as the same double;
// std::to_chars writes the same shortest text, and darc's command line reads it back.
double through_text(double v) {
  char text[32];
  const auto written = std::to_chars(text, text + sizeof text, v);
  double back = 0;
  std::from_chars(text, written.ptr, back);
  return back;
}

TEST(CropPixels, KeepsCeilOfTheStartToCeilOfTheEndMinusOne) {
  EXPECT_EQ(crop_of(72, 44, 0.3, 0.6, 0.4, 0.9), (PixelRect{22, 18, 44, 40}));
  EXPECT_EQ(crop_of(10, 10, 0, 1, 0, 1), (PixelRect{0, 0, 10, 10}));
  EXPECT_EQ(crop_of(10, 10, 0.25, 0.5, 0.05, 0.15), (PixelRect{3, 1, 5, 2}));  // 2.5 to 5: pixels 3 and 4
}

TEST(CropPixels, FractionRowsPartitionEveryResolution) {
  int checked = 0;
  for (int rows = 1; rows <= kMaxRows; ++rows) {
    std::vector<double> bounds{0.0};  // as darc-slurm writes them: 0, k/N, ..., 1
    for (int k = 1; k < rows; ++k) bounds.push_back(through_text(double(k) / rows));
    bounds.push_back(1.0);
    for (int height = rows; height <= kMaxResolution; ++height) {
      int next = 0;
      for (int k = 0; k < rows; ++k) {
        const PixelRect r = crop_of(1, height, 0, 1, bounds[size_t(k)], bounds[size_t(k) + 1]);
        // One row per pixel row (height == rows) may leave a row empty: 25 * (7/25 as a double) is
        // 7.000000000000001, so row 7 of 25 starts at pixel row 8, where row 8 does. darc-slurm
        // --tiles asks for fewer rows than the image has.
        if (r.y0 != next || (height > rows && r.height() < 1)) {
          ADD_FAILURE() << "height " << height << ", " << rows << " rows: row " << k << " is pixel rows " << r.y0
                        << " to " << r.y1 - 1 << ", expected from " << next;
          return;
        }
        next = r.y1;
      }
      ASSERT_EQ(next, height) << rows << " rows of height " << height;
      ++checked;
    }
  }
  EXPECT_GT(checked, 1000000);
}

}  // namespace
}  // namespace darc
