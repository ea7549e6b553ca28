// SceneBuilder's answer about a procedural's bound: the area it covers in the image (RunProgram's
// detail) and whether the frame wants it at all.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "parser/rib_parser.h"
#include "support/scenes_from_rib.h"

namespace darc::test {
namespace {

namespace fs = std::filesystem;

// A 100x100 frame with a 90 degree perspective camera at the origin (screen [-1, 1]^2: a point
// (x, y, z) in camera space lands at raster (50 + 50 x/z, 50 - 50 y/z)), inside its world block.
struct OpenWorld {
  Diagnostics diag{[](const Diagnostic&) {}};
  SceneBuilder builder{diag, SceneBuilder::Callbacks{}};
  OpenWorld() {
    RibParser parser(builder, diag);
    EXPECT_TRUE(
        parser.parse_string("Format 100 100 1\nProjection \"perspective\" \"fov\" [90]\nWorldBegin\n", "test.rib"));
  }
};

TEST(SceneBuilderProcedural, TheDetailIsTheBoundsAreaInTheImage) {
  OpenWorld w;
  // x, y in [-0.5, 0.5] at z = 1 .. 2: the near face spans raster [25, 75]^2.
  const ProceduralBound near_face = w.builder.procedural_bound({-0.5, 0.5, -0.5, 0.5, 1, 2}, SourceLoc{});
  EXPECT_TRUE(near_face.wanted);
  EXPECT_DOUBLE_EQ(near_face.raster_area, 2500);
  // The current transform applies: the same box moved twice as far covers a quarter of it.
  w.builder.translate(0, 0, 1, SourceLoc{});
  EXPECT_DOUBLE_EQ(w.builder.procedural_bound({-0.5, 0.5, -0.5, 0.5, 1, 3}, SourceLoc{}).raster_area, 625);
}

TEST(SceneBuilderProcedural, TheAreaIsClippedToTheImage) {
  OpenWorld w;
  // Entirely to the right of the view: nothing on screen.
  EXPECT_EQ(w.builder.procedural_bound({5, 6, -0.5, 0.5, 1, 1}, SourceLoc{}).raster_area, 0);
  // Half of it past the right edge: x/z in [0.5, 1.5] keeps raster x in [75, 100].
  EXPECT_DOUBLE_EQ(w.builder.procedural_bound({0.5, 1.5, -0.5, 0.5, 1, 1}, SourceLoc{}).raster_area, 25.0 * 50);
  // Reaching behind the eye: its projection is unbounded, so the whole image.
  EXPECT_EQ(w.builder.procedural_bound({-1, 1, -1, 1, -1, 1}, SourceLoc{}).raster_area, 100.0 * 100);
}

// In a frame --frames does not select, a procedural is neither read nor run: a missing archive
// there is no error, and the selected frame still reads its own.
TEST(SceneBuilderProcedural, AFrameThatIsNotRenderedDeclinesItsProcedurals) {
  const fs::path dir = fs::temp_directory_path() / ("darc_core_procedural_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  std::ofstream(dir / "ball.rib") << "Sphere 1 -1 1 360\n";
  const std::string dra =
      "Procedural \"DelayedReadArchive\" [\"" + (dir / "ball.rib").string() + "\"] [-1 1 -1 1 -1 1]\n";
  const std::string missing =
      "Procedural \"DelayedReadArchive\" [\"" + (dir / "missing.rib").string() + "\"] [-1 1 -1 1 -1 1]\n";
  Built b = build("FrameBegin 1\nWorldBegin\n" + missing + "WorldEnd\nFrameEnd\n" + "FrameBegin 2\nWorldBegin\n" + dra +
                      "WorldEnd\nFrameEnd\n",
                  [](int frame) { return frame == 2; });
  fs::remove_all(dir);
  EXPECT_TRUE(b.diagnostics.empty()) << b.diagnostics[0].str();
  ASSERT_EQ(b.scenes.size(), 1u);
  EXPECT_EQ(b.scenes[0].surfaces.spheres.size(), 1u);
}

TEST(SceneBuilderProcedural, InsideAnObjectTheBoundIsNotJudged) {
  OpenWorld w;
  w.builder.object_begin("tuft", SourceLoc{});
  const ProceduralBound in_object = w.builder.procedural_bound({5, 6, 5, 6, 5, 6}, SourceLoc{});
  EXPECT_TRUE(in_object.wanted);
  EXPECT_EQ(in_object.raster_area, 0) << "where the object shows is known only at ObjectInstance";
}

}  // namespace
}  // namespace darc::test
