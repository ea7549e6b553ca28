// Conformance on real RIB files from other renderers' test suites (../shared/ribs/realworld,
// see its SOURCES.md): each renders, with its documented exit code, and its image shows what
// the file describes (a property of each picture, not a golden image). Skipped with a message
// when ../shared is absent.
#include "render_test_util.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <vector>

namespace darc::test {
namespace {

fs::path realworld_ribs() { return fs::path(DARC_SHARED_RIBS_DIR) / "realworld"; }

#define REQUIRE_REALWORLD_RIBS()              \
  if (!fs::is_directory(realworld_ribs())) \
  GTEST_SKIP() << "real-world RIBs not found at " << realworld_ribs() << ": conformance skipped"

using PixelTest = std::function<bool(float r, float g, float b)>;

// Renders a file in a scratch directory (its outputs land there, named by its Display lines).
RunResult render_realworld(const ScratchDir& dir, const std::string& file, const std::string& extra = "") {
  return run_darc(dir.path(), extra + " --threads 2 '" + (realworld_ribs() / file).string() + "'");
}

int count(const Pixels& p, const PixelTest& on) {
  int n = 0;
  for (int y = 0; y < p.height; ++y)
    for (int x = 0; x < p.width; ++x)
      if (on(p.at(x, y, 0), p.at(x, y, 1), p.at(x, y, 2))) ++n;
  return n;
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

int max_runs_along_rows(const Pixels& p, const PixelTest& on) {
  int best = 0;
  for (int y = 0; y < p.height; ++y) {
    int runs = 0;
    bool prev = false;
    for (int x = 0; x < p.width; ++x) {
      const bool v = on(p.at(x, y, 0), p.at(x, y, 1), p.at(x, y, 2));
      if (v && !prev) ++runs;
      prev = v;
    }
    best = std::max(best, runs);
  }
  return best;
}

const PixelTest lit = [](float r, float g, float b) { return r + g + b > 0.15f; };

TEST(RealworldRibs, Bug940418ManyCubicStrandsAreDrawnAsSeparateBlades) {
  REQUIRE_REALWORLD_RIBS();
  ScratchDir dir("rw-940418");
  const RunResult r = render_realworld(dir, "Bugs_Bug940418_Bug940418.rib");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  Pixels img;
  ASSERT_TRUE(read_image(dir / "Bug940418.tif", img));
  EXPECT_EQ(img.width, 320);
  EXPECT_GT(count(img, lit), 300) << "a tuft of plastic strands in the middle of the frame";
  EXPECT_GE(max_runs_along_rows(img, lit), 8) << "many strands cross one row";
}

TEST(RealworldRibs, BezierGrassIsGreenTaperingBlades) {
  REQUIRE_REALWORLD_RIBS();
  ScratchDir dir("rw-bezier");
  const RunResult r = render_realworld(dir, "content_ribs_features_curves_bezier.rib");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("additional displays"), std::string::npos) << "the framebuffer display is reported";
  Pixels img;
  ASSERT_TRUE(read_image(dir / "bezier.tif", img));
  EXPECT_EQ(img.width, 480);
  const PixelTest green = [](float r, float g, float b) { return g > 0.05f && g > 1.5f * r && g > 1.5f * b; };
  EXPECT_GT(count(img, green), 4000);
  EXPECT_EQ(count(img, [](float r, float g, float b) { return r > g + 0.02f || b > g + 0.02f; }), 0)
      << "nothing but grass";
  EXPECT_GE(max_runs_along_rows(img, green), 12) << "many separate blades";
}

TEST(RealworldRibs, DelayedReadArchiveBringsInItsSphere) {
  REQUIRE_REALWORLD_RIBS();
  ScratchDir dir("rw-delayed");
  const RunResult r = render_realworld(dir, "delayedproc.rib");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  Pixels img;
  ASSERT_TRUE(read_image(dir / "delayedproc.tif", img));
  const PixelTest yellow = [](float r, float g, float b) { return r > 0.5f && g > 0.5f && b < 0.2f; };
  const std::vector<int> discs = regions(img, yellow, 50);
  ASSERT_EQ(discs.size(), 1u) << "one constant-shaded sphere from the archive";
  EXPECT_EQ(count(img, [](float r, float g, float b) { return b > 0.02f || std::abs(r - g) > 0.02f; }), 0)
      << "nothing else in the frame: every other pixel is black or a yellow edge";
}

TEST(RealworldRibs, ArchiveAloneIsAnErrorOutsideTheWorld) {
  REQUIRE_REALWORLD_RIBS();
  ScratchDir dir("rw-archive");
  // delayed_archive.rib is the archive delayedproc.rib reads: a bare Sphere, meaningless alone.
  const RunResult r = render_realworld(dir, "delayed_archive.rib");
  EXPECT_EQ(r.exit_code, 3);
  EXPECT_NE(r.err.find("delayed_archive.rib:1:1: error: Sphere: Sphere outside WorldBegin/WorldEnd"),
            std::string::npos)
      << r.err;
}

TEST(RealworldRibs, VolumeBoxEdgesAreLinearCurves) {
  REQUIRE_REALWORLD_RIBS();
  ScratchDir dir("rw-volume");
  const RunResult r = render_realworld(dir, "tools_shadeops_sci_volumes_volume.rib");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("Atmosphere: not supported"), std::string::npos) << r.err;
  Pixels img;
  ASSERT_TRUE(read_image(dir / "volume.tif", img));
  EXPECT_EQ(img.width, 640);
  const PixelTest bright = [](float r, float g, float b) { return r + g + b > 1.5f; };
  const std::vector<int> edges = regions(img, bright, 200);
  ASSERT_GE(edges.size(), 1u);
  EXPECT_GT(edges[0], 2000) << "the twelve edges of the box are joined at its corners";
  EXPECT_LT(count(img, bright), img.width * img.height / 10) << "thin lines, not filled faces";
}

}  // namespace
}  // namespace darc::test
