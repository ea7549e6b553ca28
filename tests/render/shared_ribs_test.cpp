// Conformance: every RIB file in ../shared/ribs/aqsis renders with exit code 0, and each image
// shows what the file is about. Skipped (with a message) when ../shared is absent.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "support/darc_command.h"
#include "support/pixel_counts.h"
#include "support/shared_ribs.h"

namespace darc::test {
namespace {

// Renders a shared RIB in a scratch directory (outputs land there, named by Display) and reads
// `image`, the one the test looks at.
FileRender render_shared(const ScratchDir& dir, const std::string& file, const std::string& image,
                         const std::string& extra = "") {
  return render_file(dir, shared_ribs("aqsis") / file, extra, image);
}

TEST(SharedRibs, BezierGrassShowsManyTaperingBlades) {
  SKIP_WITHOUT_SHARED_RIBS("aqsis");
  ScratchDir dir("bezier");
  const FileRender f = render_shared(dir, "Curves_bezier.rib", "bezier.tif");
  ASSERT_TRUE(rendered_cleanly(f));
  const Pixels& img = *f.image;
  EXPECT_EQ(img.width, 320);
  EXPECT_EQ(img.height, 240);
  // The point light sits near the camera, so the camera-facing blades catch the plastic
  // highlight and saturate towards white; unsaturated pixels are green.
  auto lit = [](float r, float g, float b) { return r + g + b > 0.3f; };
  auto green = [](float r, float g, float b) { return g > r + 0.05f && g > b + 0.05f; };
  int n = count_pixels(img, lit);
  EXPECT_GT(n, 2000) << "grass should cover a good part of the frame";
  EXPECT_LT(n, 320 * 240 / 2);
  EXPECT_GT(count_pixels(img, green), 1000);
  EXPECT_EQ(count_pixels(img, [](float r, float g, float b) { return r > g + 0.05f || b > g + 0.05f; }), 0)
      << "nothing but grass colours";
  // Many separate blades cross one image row.
  EXPECT_GE(max_runs_along_rows(img, lit), 8) << "expected many separate blades across a row";
}

TEST(SharedRibs, CatmullRomCurveAndReferenceSquare) {
  SKIP_WITHOUT_SHARED_RIBS("aqsis");
  ScratchDir dir("catmull");
  const FileRender f = render_shared(dir, "Curves_catmull-rom.rib", "catmull-rom.tif");
  ASSERT_TRUE(rendered_cleanly(f));
  const Pixels& img = *f.image;
  // Surface "constant" with Color 0.8 0.8 1.0: the curve pixels are exactly that colour (8-bit
  // sRGB of 0.8 is 231/255 = 0.906).
  auto lilac = [](float r, float g, float b) { return b > 0.95f && r > 0.85f && r < 0.95f && g > 0.85f && g < 0.95f; };
  int n = count_pixels(img, lilac);
  EXPECT_GT(n, 200);
  EXPECT_LT(n, 320 * 240 / 4);
}

TEST(SharedRibs, LinearCurveSeenEndOnAndSquare) {
  SKIP_WITHOUT_SHARED_RIBS("aqsis");
  ScratchDir dir("linear");
  const FileRender f = render_shared(dir, "Curves_linear.rib", "linear.tif");
  ASSERT_TRUE(rendered_cleanly(f));
  const Pixels& img = *f.image;
  auto lit = [](float r, float g, float b) { return r + g + b > 0.5f; };
  EXPECT_GT(count_pixels(img, lit), 100);
}

TEST(SharedRibs, LinCurveTest1FallsBackFromUnknownShader) {
  SKIP_WITHOUT_SHARED_RIBS("aqsis");
  ScratchDir dir("lincurve1");
  const FileRender f = render_shared(dir, "Curves_lincurve_test1.rib", "lincurve_test1.tif");
  ASSERT_TRUE(rendered_cleanly(f));
  EXPECT_NE(f.run.err.find("show_st"), std::string::npos) << "expected a warning naming the unknown shader";
  const Pixels& img = *f.image;
  auto lit = [](float r, float g, float b) { return r + g + b > 0.3f; };
  EXPECT_GT(count_pixels(img, lit), 2000);
}

TEST(SharedRibs, LinCurveTest2OneSidedCurveShowsLessThanTwoSided) {
  SKIP_WITHOUT_SHARED_RIBS("aqsis");
  ScratchDir dir("lincurve2");
  const FileRender f = render_shared(dir, "Curves_lincurve_test2.rib", "lincurve_test2.tif");
  ASSERT_TRUE(rendered_cleanly(f));
  const Pixels& img = *f.image;
  auto blue = [](float r, float g, float b) { return b > 0.05f && r < 0.5f * b && g < 0.5f * b; };
  auto purple = [](float r, float g, float b) { return r > 0.05f && b > 0.05f && g < 0.5f * std::min(r, b); };
  auto red = [](float r, float g, float b) { return r > 0.05f && g < 0.3f * r && b < 0.3f * r; };
  auto green = [](float r, float g, float b) { return g > 0.05f && r < 0.3f * g && b < 0.3f * g; };
  int nb = count_pixels(img, blue), np = count_pixels(img, purple);
  EXPECT_GT(nb, 200);
  EXPECT_GT(np, 50) << "the one-sided curve shows its front faces";
  EXPECT_LT(np, nb) << "Sides 1 hides the back-facing half of the purple curve";
  EXPECT_GT(count_pixels(img, red), 100);
  EXPECT_GT(count_pixels(img, green), 500);
}

TEST(SharedRibs, AnimWritesFiftyFramesWithAMovingSphere) {
  SKIP_WITHOUT_SHARED_RIBS("aqsis");
  ScratchDir dir("anim");
  ASSERT_TRUE(rendered_cleanly(render_shared(dir, "Misc_anim.rib", "anim00.tif", "--res 80x60")));
  double cx_first = 0, cx_prev = -1;
  int moved = 0;
  for (int f = 0; f < 50; ++f) {
    char name[32];
    std::snprintf(name, sizeof name, "anim%02d.tif", f);
    Pixels img;
    ASSERT_TRUE(read_image(dir / name, img)) << name;
    ASSERT_EQ(img.channels, 4) << "rgba display";
    double sx = 0, sw = 0;
    for (int y = 0; y < img.height; ++y)
      for (int x = 0; x < img.width; ++x) {
        float a = img.at(x, y, 3);
        sx += a * x;
        sw += a;
      }
    ASSERT_GT(sw, 10) << "the sphere is visible in " << name;
    double cx = sx / sw;
    if (f == 0) cx_first = cx;
    if (cx_prev >= 0 && std::abs(cx - cx_prev) > 0.05) ++moved;
    cx_prev = cx;
  }
  EXPECT_GT(moved, 25) << "the sphere moves between most frames";
  (void)cx_first;
}

TEST(SharedRibs, GeneralPolygonsHaveHoles) {
  SKIP_WITHOUT_SHARED_RIBS("aqsis");
  ScratchDir dir("genpoly");
  const FileRender f = render_shared(dir, "Polygons_genpoly_test.rib", "genpoly_test.tif");
  ASSERT_TRUE(rendered_cleanly(f));
  const Pixels& img = *f.image;
  auto red = [](float r, float g, float b) { return r > 0.2f && g < 0.4f * r && b < 0.4f * r; };
  auto yellow = [](float r, float g, float b) { return r > 0.2f && g > 0.6f * r && b < 0.4f * r; };
  EXPECT_GT(count_pixels(img, red), 500);
  EXPECT_GT(count_pixels(img, yellow), 100) << "the yellow polygon shows through the red polygon's hole";
  // Background shows through the holes: some pixels inside the red polygons' bounding box are
  // black (alpha 0).
  int transparent = 0;
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x)
      if (img.at(x, y, 3) < 0.01f) ++transparent;
  EXPECT_GT(transparent, 1000);
}

TEST(SharedRibs, ReadArchiveBringsTheRedTriangle) {
  SKIP_WITHOUT_SHARED_RIBS("aqsis");
  ScratchDir dir("readarchive");
  const FileRender f = render_shared(dir, "RIBProcessing_readarchive.rib", "readarchive.tif");
  ASSERT_TRUE(rendered_cleanly(f));
  const Pixels& img = *f.image;
  auto red = [](float r, float g, float b) { return r > 0.9f && g < 0.1f && b < 0.1f; };
  auto yellow = [](float r, float g, float b) { return r > 0.9f && g > 0.9f && b < 0.1f; };
  auto white = [](float r, float g, float b) { return r > 0.9f && g > 0.9f && b > 0.9f; };
  EXPECT_GT(count_pixels(img, red), 100) << "the archive's triangle";
  EXPECT_GT(count_pixels(img, yellow), 100);
  EXPECT_GT(count_pixels(img, white), 100);
  // The yellow square is in front, at the centre.
  EXPECT_TRUE(yellow(img.at(100, 75, 0), img.at(100, 75, 1), img.at(100, 75, 2)));
}

}  // namespace
}  // namespace darc::test
