// The distance-aware hider end to end on small scenes built from RIB text: one fragment per
// strand per ray across segment joints and grid cells, and compositing with surfaces.
#include "integrator/distance_hider.h"

#include <gtest/gtest.h>

#include <optional>
#include <sstream>
#include <string>

#include "support/render.h"
#include "support/scenes_from_rib.h"
#include "support/test_frames.h"

namespace darc {
namespace {

using test::build_scene;
using test::orthographic_frame;
using test::render;
using test::RenderedFrame;
using test::single_thread;

constexpr int kWidth = 16, kHeight = 4;
constexpr float kStrandWidth = 0.3f;
// World y of the centres of raster row 1 (rows are 1 unit high, y up).
constexpr float kRowOneCentreY = 0.5f;

// A straight strand along x through the centres of raster row 1, with a vertex at every pixel
// centre (so every camera ray passes exactly through a joint between two segments).
std::string strand_with_joints_at_pixel_centres(bool cubic) {
  std::ostringstream s;
  const int vertices_per_unit = cubic ? 3 : 1;  // cubic Bézier: 3 vertices per segment
  // From 1.5 units left of the image to 1.5 right of it (no strand end is seen): segment joints
  // at -9.5, -8.5, ..., 9.5, which include every pixel centre -7.5 ... 7.5.
  const float first = -0.5f * kWidth - 1.5f;
  const int n = (kWidth + 3) * vertices_per_unit + 1;
  s << (cubic ? "Basis \"bezier\" 3 \"bezier\" 3\nCurves \"cubic\" [" : "Curves \"linear\" [") << n
    << "] \"nonperiodic\" \"P\" [";
  for (int i = 0; i < n; ++i) s << first + float(i) / float(vertices_per_unit) << " " << kRowOneCentreY << " 5 ";
  s << "] \"constantwidth\" [" << kStrandWidth << "]\n";
  return s.str();
}

TEST(DistanceHider, OneFragmentPerStrandAcrossJointsAndCells) {
  for (bool cubic : {false, true}) {
    SCOPED_TRACE(cubic ? "cubic" : "linear");
    Scene scene = build_scene(orthographic_frame(kWidth, kHeight, 1, strand_with_joints_at_pixel_centres(cubic)));
    ASSERT_GE(scene.curves.size(), size_t(kWidth));
    if (scene.accel.kind() == AcceleratorKind::Grid) {
      EXPECT_GE(scene.accel.grid().resolution()[0], kWidth / 2);  // the strand spans many cells
    }
    const RenderedFrame frame = render(scene, single_thread(HiderKind::Distance));
    const Image& image = frame.image;
    int alpha = image.channel_index("A");
    for (int x = 0; x < kWidth; ++x) {
      // The band [-0.15, 0.15] inside the unit pixel: coverage 0.3, not 1 - 0.7^2 = 0.51.
      EXPECT_NEAR(image.at(x, 1, alpha), kStrandWidth, 1e-4f) << "pixel " << x;
      for (int y : {0, 2, 3}) EXPECT_EQ(image.at(x, y, alpha), 0.0f) << x << "," << y;
    }
    EXPECT_EQ(frame.stats.counters.fragments, uint64_t(kWidth));  // one per ray that sees the strand
  }
}

TEST(DistanceHider, StrandOverAndUnderAnOpaqueSurface) {
  const std::string quad_at_10 = "Color 0 0 1\nPolygon \"P\" [-20 -20 10  20 -20 10  20 20 10  -20 20 10]\n";
  auto strand_at = [](float z) {
    std::ostringstream s;
    s << "Color 1 0 0\nCurves \"linear\" [2] \"nonperiodic\" \"P\" [-20 " << kRowOneCentreY << " " << z << " 20 "
      << kRowOneCentreY << " " << z << "] \"constantwidth\" [" << kStrandWidth << "]\n";
    return s.str();
  };
  Scene front = build_scene(orthographic_frame(kWidth, kHeight, 1, quad_at_10 + strand_at(5)));
  Image image = render(front, single_thread(HiderKind::Distance)).image;
  // Premultiplied red over blue: (0.3, 0, 0.7), alpha 1.
  EXPECT_NEAR(image.at(3, 1, 0), kStrandWidth, 1e-4f);
  EXPECT_NEAR(image.at(3, 1, 2), 1.0f - kStrandWidth, 1e-4f);
  EXPECT_NEAR(image.at(3, 1, image.channel_index("A")), 1.0f, 1e-5f);
  EXPECT_NEAR(image.at(3, 0, 2), 1.0f, 1e-5f);
  Scene behind = build_scene(orthographic_frame(kWidth, kHeight, 1, quad_at_10 + strand_at(15)));
  image = render(behind, single_thread(HiderKind::Distance)).image;
  EXPECT_EQ(image.at(3, 1, 0), 0.0f);
  EXPECT_NEAR(image.at(3, 1, 2), 1.0f, 1e-5f);
}

}  // namespace
}  // namespace darc
