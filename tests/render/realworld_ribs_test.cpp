// Conformance on real RIB files from other renderers' test suites (../shared/ribs/realworld,
// see its SOURCES.md): each renders, with its documented exit code, and its image shows what
// the file describes (a property of each picture, not a golden image). Skipped with a message
// when ../shared is absent.
#include <algorithm>
#include <cmath>
#include <vector>

#include "support/darc_command.h"
#include "support/image_compare.h"
#include "support/pixel_counts.h"
#include "support/shared_ribs.h"

namespace darc::test {
namespace {

// Renders a file in a scratch directory (its outputs land there, named by its Display lines) and
// reads `image`, the one the test looks at.
FileRender render_realworld(const ScratchDir& dir, const std::string& file, const std::string& image,
                            const std::string& extra = "") {
  return render_file(dir, shared_ribs("realworld") / file, extra + " --threads 2", image);
}

// The sizes of the 4-connected regions of "on" pixels with at least min_size pixels, largest first.
std::vector<int> regions(const Pixels& p, const PixelTest& on, int min_size) {
  std::vector<int> label(size_t(p.width) * p.height, -1), sizes;
  for (int y0 = 0; y0 < p.height; ++y0)
    for (int x0 = 0; x0 < p.width; ++x0) {
      const size_t start = size_t(y0) * p.width + x0;
      if (label[start] >= 0 || !on(p.at(x0, y0, 0), p.at(x0, y0, 1), p.at(x0, y0, 2))) continue;
      const int id = int(sizes.size());
      int size = 0;
      std::vector<std::pair<int, int>> stack{{x0, y0}};
      label[start] = id;
      while (!stack.empty()) {
        auto [x, y] = stack.back();
        stack.pop_back();
        ++size;
        const int nx[4] = {x + 1, x - 1, x, x}, ny[4] = {y, y, y + 1, y - 1};
        for (int k = 0; k < 4; ++k) {
          if (nx[k] < 0 || ny[k] < 0 || nx[k] >= p.width || ny[k] >= p.height) continue;
          const size_t i = size_t(ny[k]) * p.width + nx[k];
          if (label[i] >= 0 || !on(p.at(nx[k], ny[k], 0), p.at(nx[k], ny[k], 1), p.at(nx[k], ny[k], 2))) continue;
          label[i] = id;
          stack.push_back({nx[k], ny[k]});
        }
      }
      sizes.push_back(size);
    }
  std::vector<int> big;
  for (int s : sizes)
    if (s >= min_size) big.push_back(s);
  std::sort(big.rbegin(), big.rend());
  return big;
}

const PixelTest lit = [](float r, float g, float b) { return r + g + b > 0.15f; };

TEST(RealworldRibs, Bug940418ManyCubicStrandsAreDrawnAsSeparateBlades) {
  SKIP_WITHOUT_SHARED_RIBS("realworld");
  ScratchDir dir("rw-940418");
  const FileRender f = render_realworld(dir, "Bugs_Bug940418_Bug940418.rib", "Bug940418.tif");
  ASSERT_TRUE(rendered_cleanly(f));
  const Pixels& img = *f.image;
  EXPECT_EQ(img.width, 320);
  EXPECT_GT(count_pixels(img, lit), 300) << "a tuft of plastic strands in the middle of the frame";
  EXPECT_GE(max_runs_along_rows(img, lit), 8) << "many strands cross one row";
}

TEST(RealworldRibs, BezierGrassIsGreenTaperingBlades) {
  SKIP_WITHOUT_SHARED_RIBS("realworld");
  ScratchDir dir("rw-bezier");
  const FileRender f = render_realworld(dir, "content_ribs_features_curves_bezier.rib", "bezier.tif");
  ASSERT_TRUE(rendered_cleanly(f));
  EXPECT_NE(f.run.err.find("additional displays"), std::string::npos) << "the framebuffer display is reported";
  const Pixels& img = *f.image;
  EXPECT_EQ(img.width, 480);
  const PixelTest green = [](float r, float g, float b) { return g > 0.05f && g > 1.5f * r && g > 1.5f * b; };
  EXPECT_GT(count_pixels(img, green), 4000);
  EXPECT_EQ(count_pixels(img, [](float r, float g, float b) { return r > g + 0.02f || b > g + 0.02f; }), 0)
      << "nothing but grass";
  EXPECT_GE(max_runs_along_rows(img, green), 12) << "many separate blades";
}

TEST(RealworldRibs, DelayedReadArchiveBringsInItsSphere) {
  SKIP_WITHOUT_SHARED_RIBS("realworld");
  ScratchDir dir("rw-delayed");
  const FileRender f = render_realworld(dir, "delayedproc.rib", "delayedproc.tif");
  ASSERT_TRUE(rendered_cleanly(f));
  const Pixels& img = *f.image;
  const PixelTest yellow = [](float r, float g, float b) { return r > 0.5f && g > 0.5f && b < 0.2f; };
  const std::vector<int> discs = regions(img, yellow, 50);
  ASSERT_EQ(discs.size(), 1u) << "one constant-shaded sphere from the archive";
  EXPECT_EQ(count_pixels(img, [](float r, float g, float b) { return b > 0.02f || std::abs(r - g) > 0.02f; }), 0)
      << "nothing else in the frame: every other pixel is black or a yellow edge";
}

TEST(RealworldRibs, ArchiveAloneIsAnErrorOutsideTheWorld) {
  SKIP_WITHOUT_SHARED_RIBS("realworld");
  ScratchDir dir("rw-archive");
  // delayed_archive.rib is the archive delayedproc.rib reads: a bare Sphere, meaningless alone.
  const RunResult r = render_realworld(dir, "delayed_archive.rib", /*image=*/"").run;
  EXPECT_EQ(r.exit_code, 3);
  EXPECT_NE(r.err.find("delayed_archive.rib:1:1: error: Sphere: Sphere outside WorldBegin/WorldEnd"),
            std::string::npos)
      << r.err;
}

TEST(RealworldRibs, VolumeBoxEdgesAreLinearCurves) {
  SKIP_WITHOUT_SHARED_RIBS("realworld");
  ScratchDir dir("rw-volume");
  const FileRender f = render_realworld(dir, "tools_shadeops_sci_volumes_volume.rib", "volume.tif");
  ASSERT_TRUE(rendered_cleanly(f));
  EXPECT_NE(f.run.err.find("Atmosphere: not supported"), std::string::npos) << f.run.err;
  const Pixels& img = *f.image;
  EXPECT_EQ(img.width, 640);
  const PixelTest bright = [](float r, float g, float b) { return r + g + b > 1.5f; };
  const std::vector<int> edges = regions(img, bright, 200);
  ASSERT_GE(edges.size(), 1u);
  EXPECT_GT(edges[0], 2000) << "the twelve edges of the box are joined at its corners";
  EXPECT_LT(count_pixels(img, bright), img.width * img.height / 10) << "thin lines, not filled faces";
}

TEST(RealworldRibs, Bug1102598UnknownBasisIsAnErrorAndTheCurvesStillDrawOverTheWhitePatch) {
  SKIP_WITHOUT_SHARED_RIBS("realworld");
  ScratchDir dir("rw-1102598");
  const FileRender f = render_realworld(dir, "Bugs_Bug1102598_Bug1102598.rib", "Bug1102598.tif");
  EXPECT_EQ(f.run.exit_code, 3) << "an unknown basis name is an error (the image is still written)";
  EXPECT_NE(f.run.err.find("Bugs_Bug1102598_Bug1102598.rib:19:1: error: Basis: unknown basis \"spam\""),
            std::string::npos)
      << f.run.err;
  ASSERT_TRUE(f.image.has_value());
  const Pixels& img = *f.image;
  const auto header = read_image_header(dir / "Bug1102598.tif");
  ASSERT_TRUE(header.has_value());
  // TIFF has no custom attributes: the error count goes in its ImageDescription.
  EXPECT_NE(header->get_string_attribute("ImageDescription").find("darc:errors=1"), std::string::npos)
      << "the image says it was rendered despite errors";
  const PixelTest white = [](float r, float g, float b) { return std::min({r, g, b}) > 0.9f; };
  EXPECT_GT(count_pixels(img, white), img.width * img.height * 8 / 10)
      << "the constant white bilinear Patch fills the view";
  const PixelTest red = [](float r, float g, float b) { return r > 0.6f && g < 0.6f && b < 0.6f; };
  EXPECT_GT(count_pixels(img, red), 150) << "the red cubic curve (the previous basis: the unknown one is not applied)";
  const PixelTest hull = [](float r, float g, float b) { return r > 0.6f && g > 0.6f && b < 0.75f && b < r - 0.1f; };
  EXPECT_GT(count_pixels(img, hull), 100) << "the yellowish linear control polygon";
}

TEST(RealworldRibs, ShadowposCurvesAndSphereShadowTheGroundPatch) {
  SKIP_WITHOUT_SHARED_RIBS("realworld");
  ScratchDir dir("rw-shadowpos");
  const FileRender f = render_realworld(dir, "Shadows_shadowpos_1.rib", "shadowpos_1.tif");
  ASSERT_TRUE(rendered_cleanly(f));
  EXPECT_NE(f.run.err.find("unknown light shader \"spot\""), std::string::npos)
      << "the custom light falls back, said so";
  EXPECT_TRUE(fs::exists(dir / "shadow.z.tif")) << "the shadow-map pass is rendered as a depth image";
  const Pixels& img = *f.image;
  EXPECT_EQ(img.width, 320);
  const PixelTest ground = [](float r, float g, float b) { return r > 0.3f && r >= g && g >= b - 0.01f && r - b < 0.2f; };
  const PixelTest green = [](float r, float g, float b) { return g > 0.15f && g > 2 * r && g > 2 * b; };
  const PixelTest yellow = [](float r, float g, float b) { return r > 0.3f && g > 0.3f && b < 0.5f * g; };
  EXPECT_GT(count_pixels(img, ground), img.width * img.height / 3) << "the matte Patch ground";
  EXPECT_GT(count_pixels(img, green), 2000) << "the green sphere";
  EXPECT_GT(count_pixels(img, yellow), 1000) << "the yellow strands";
  // Below the strands, on the ground, their shadow and the sphere's: dark pixels in the lower
  // half, where without the ground there would be only background.
  const PixelTest dark = [](float r, float g, float b) { return r + g + b < 0.1f; };
  int dark_low = 0;
  for (int y = img.height / 2; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x)
      if (dark(img.at(x, y, 0), img.at(x, y, 1), img.at(x, y, 2))) ++dark_low;
  EXPECT_GT(dark_low, 1000) << "a shadow on the ground";
}

TEST(RealworldRibs, ShadtestSphereCastsAShadowOnTheGroundPatch) {
  SKIP_WITHOUT_SHARED_RIBS("realworld");
  ScratchDir dir("rw-shadtest");
  const FileRender f = render_realworld(dir, "Shadows_shadtest.rib", "shadtest.tif");
  ASSERT_TRUE(rendered_cleanly(f));
  const Pixels& img = *f.image;
  EXPECT_EQ(img.width, 200);
  EXPECT_EQ(img.height, 150);
  // The ground fills the lower half of the frame, lit by the spot except in the sphere's shadow,
  // which only the ambient light (0.2) reaches: a region of ground there at under half the
  // brightness of the lit ground.
  float lit_max = 0;
  for (int y = img.height / 2; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) lit_max = std::max(lit_max, img.at(x, y, 0) + img.at(x, y, 1) + img.at(x, y, 2));
  EXPECT_GT(lit_max, 1.5f) << "the spot lights the ground";
  Pixels lower = img;
  for (int y = 0; y < img.height / 2; ++y)
    for (int x = 0; x < img.width; ++x)
      for (int c = 0; c < 3; ++c) lower.v[(size_t(y) * img.width + x) * img.channels + c] = 0;
  const PixelTest shadowed = [&](float r, float g, float b) { return r + g + b > 0.1f && r + g + b < 0.5f * lit_max; };
  const std::vector<int> shadows = regions(lower, shadowed, 200);
  ASSERT_GE(shadows.size(), 1u) << "a shadow region on the ground";
  EXPECT_GT(shadows[0], 600) << "the sphere's shadow";
  EXPECT_EQ(count_pixels(lower, [](float r, float g, float b) { return r + g + b <= 0.1f; }),
            img.width * img.height / 2)
      << "no background below the horizon: the ground Patch is there";
}

TEST(RealworldRibs, Subdiv1IsOneSmoothLimitSurface) {
  SKIP_WITHOUT_SHARED_RIBS("realworld");
  ScratchDir dir("rw-subdiv1");
  const FileRender f = render_realworld(dir, "Subdivision_subdiv1.rib", "subdiv1.tif");
  ASSERT_TRUE(rendered_cleanly(f));
  EXPECT_EQ(f.run.err.find("nothing renderable"), std::string::npos) << f.run.err;
  const Pixels& img = *f.image;
  const std::vector<int> blobs = regions(img, lit, 20);
  ASSERT_EQ(blobs.size(), 1u) << "the subdivided tetrahedron is one surface";
  EXPECT_GT(blobs[0], img.width * img.height / 8);
  // Smooth: inside the surface, neighbouring pixels differ little (facets would show as steps).
  // Pixels within 4 of the outline are left out: toward the limb the shading changes fast.
  constexpr int kRim = 4;
  double worst = 0;
  for (int y = kRim; y < img.height - kRim; ++y)
    for (int x = kRim; x < img.width - kRim; ++x) {
      bool inside = true;
      for (int dy = -kRim; dy <= kRim; ++dy)
        for (int dx = -kRim; dx <= kRim; ++dx) inside = inside && img.at(x + dx, y + dy, 3) > 0.999f;
      if (!inside) continue;
      // The second difference: large at a crease between flat facets, small on smooth shading
      // however steep (toward the limb of a strongly lit surface).
      auto sum = [&](int px, int py) { return double(img.at(px, py, 0) + img.at(px, py, 1) + img.at(px, py, 2)); };
      const double s = sum(x, y);
      worst = std::max({worst, std::abs(sum(x - 1, y) - 2 * s + sum(x + 1, y)),
                        std::abs(sum(x, y - 1) - 2 * s + sum(x, y + 1))});
    }
  EXPECT_LT(worst, 0.05) << "no facet edges inside the surface";
}

TEST(RealworldRibs, TmapTestShowsItsFivePatchesDiskAndPolygons) {
  SKIP_WITHOUT_SHARED_RIBS("realworld");
  ScratchDir dir("rw-tmap");
  const FileRender f = render_realworld(dir, "Texturing_tmap_test.rib", "tmap_test.tif");
  ASSERT_TRUE(rendered_cleanly(f));
  EXPECT_EQ(f.run.err.find("is not supported: skipped"), std::string::npos)
      << "every primitive is drawn: " << f.run.err;
  const Pixels& img = *f.image;
  const std::vector<int> objects = regions(img, lit, 100);
  // A bilinear Patch, a bicubic Patch, a Disk, PointsPolygons, a periodic bicubic PatchMesh and a
  // bilinear PatchMesh: four separate regions in the picture (two pairs touch).
  EXPECT_GE(objects.size(), 4u);
  EXPECT_GT(count_pixels(img, lit), img.width * img.height / 4);
}

TEST(RealworldRibs, DeformationShowsEveryPrimitiveKind) {
  SKIP_WITHOUT_SHARED_RIBS("realworld");
  ScratchDir dir("rw-deformation");
  const FileRender f = render_realworld(dir, "content_ribs_features_motionblur_deformation.rib", "deformation.tif");
  ASSERT_TRUE(rendered_cleanly(f));
  // Everything moves: the two Curves, the polygons, the subdivision mesh, the quadrics and the
  // points.
  EXPECT_EQ(f.run.err.find("motion blur of"), std::string::npos) << "everything moves: " << f.run.err;
  EXPECT_EQ(f.run.err.find("do not tessellate alike"), std::string::npos);
  EXPECT_EQ(f.run.err.find("is not supported: skipped"), std::string::npos)
      << "every primitive is drawn: " << f.run.err;
  const Pixels& img = *f.image;
  // Subdivision surface, sphere, cylinder, cone, hyperboloid, paraboloid, disk, polygons: each
  // drawn at its place in the grid's top two rows; and the four Points, a few pixels each, in the
  // bottom row on the left (the blurred curves are to their right).
  const int centres[8][2] = {{75, 65}, {130, 58}, {185, 65}, {250, 70}, {85, 118}, {130, 112}, {175, 120}, {233, 120}};
  for (const auto& c : centres) {
    int on = 0;
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx)
        on += lit(img.at(c[0] + dx, c[1] + dy, 0), img.at(c[0] + dx, c[1] + dy, 1), img.at(c[0] + dx, c[1] + dy, 2));
    EXPECT_EQ(on, 9) << "a shape at " << c[0] << ", " << c[1];
  }
  Pixels left = img;
  for (int y = 0; y < left.height; ++y)
    for (int x = 0; x < left.width; ++x)
      if (y < 140 || x >= 110)
        for (int c = 0; c < left.channels; ++c) left.v[(size_t(y) * left.width + x) * left.channels + c] = 0;
  EXPECT_EQ(regions(left, lit, 3).size(), 4u) << "the four points";
  // Under the disk, the linear curve turns about its right end through a quarter turn and the
  // cubic one bends down: a fan of partial coverage (sharp curves would cover some 300 pixels).
  int partial = 0;
  for (int y = 140; y < 230; ++y)
    for (int x = 110; x < 210; ++x) partial += img.at(x, y, 3) > 0.01f && img.at(x, y, 3) < 0.5f;
  EXPECT_GT(partial, 1500) << "the curves' motion blur";
}

TEST(RealworldRibs, VaseAndTeapotPatchMeshesRenderInTheirLastFrame) {
  SKIP_WITHOUT_SHARED_RIBS("realworld");
  ScratchDir dir("rw-vase");
  // With the default (distance) hider, at half its resolution to keep the test short under the
  // sanitizers.
  const FileRender f = render_realworld(dir, "content_ribs_scenes_vase_vase.rib", "vase.tif", "--res 128x96");
  ASSERT_TRUE(rendered_cleanly(f));
  EXPECT_EQ(f.run.err.find("nothing renderable"), std::string::npos) << f.run.err;
  EXPECT_TRUE(fs::exists(dir / "shad1.map.tif") && fs::exists(dir / "shad2.map.tif")) << "the two shadow passes";
  const Pixels& img = *f.image;
  EXPECT_EQ(img.width, 128);
  EXPECT_EQ(img.height, 96);
  const PixelTest vase = [](float r, float g, float b) { return g > r + 0.03f && g > b + 0.03f; };
  const PixelTest bright = [](float r, float g, float b) { return std::min({r, g, b}) > 0.6f; };
  const std::vector<int> vases = regions(img, vase, 100);
  ASSERT_GE(vases.size(), 1u);
  EXPECT_GT(vases[0], 600) << "the green vase";
  EXPECT_GT(count_pixels(img, bright), 1000) << "the white teapot and the lit floor";
}

TEST(RealworldRibs, VaseWithTheDefaultHiderIsCloserToTheReferenceThanOneSampleAPixel) {
  // The vase's frame 3 (two shadowing spot lights over a patch-mesh floor) with the distance
  // hider at 1 sample a pixel, against the stochastic hider at 8x8: closer than the stochastic
  // hider at 1x1, and no farther than at 2x2. Before analytic surface coverage and shadow pencils the distance hider lost the
  // shadows and striped the floor (0.046 at full size, worse than stochastic 1x1's 0.038).
  SKIP_WITHOUT_SHARED_RIBS("realworld");
  ScratchDir dir("rw-vase-default");
  auto render = [&](const std::string& args, const std::string& name) {
    const FileRender f = render_realworld(dir, "content_ribs_scenes_vase_vase.rib", name,
                                          "--res 128x96 --frames 3 -o " + name + " " + args);
    EXPECT_TRUE(rendered_cleanly(f)) << name;
    return f.image.value_or(Pixels{});
  };
  const Pixels reference = render("--hider stochastic --pixel-samples 8", "reference.exr");
  const Pixels stochastic = render("--hider stochastic --pixel-samples 1", "stochastic1.exr");
  const Pixels stochastic2 = render("--hider stochastic --pixel-samples 2", "stochastic2.exr");
  const Pixels distance = render("--pixel-samples 1", "distance1.exr");
  ASSERT_EQ(distance.width, reference.width);
  const double distance_error = compare(distance, reference).rmse,
               stochastic_error = compare(stochastic, reference).rmse,
               stochastic2_error = compare(stochastic2, reference).rmse;
  EXPECT_LT(distance_error, 0.6 * stochastic_error)
      << "distance 1x1 RMSE " << distance_error << ", stochastic 1x1 " << stochastic_error;
  // Issue 18's "correct first": no worse than stochastic 2x2. Surfaces shaded where they are seen
  // made it so (0.01398 -> 0.01322, stochastic 2x2 0.01337): the vase's foot and the floor under
  // it were shaded where neither is seen.
  EXPECT_LE(distance_error, stochastic2_error)
      << "distance 1x1 RMSE " << distance_error << ", stochastic 2x2 " << stochastic2_error;
}

}  // namespace
}  // namespace darc::test
