// End-to-end: the parameter audit's decisions that only a render shows (docs/parameters.md): the
// reflection depth cap that keeps two facing mirrors from overflowing the stack, a crop window
// without a pixel (an error at the request, not an I/O failure), and extreme frame numbers in
// file names and frame lists.
#include <nlohmann/json.hpp>

#include "support/darc_command.h"
#include "support/image_files.h"
#include "support/test_frames.h"

namespace darc::test {
namespace {

constexpr int kExitOk = 0;
constexpr int kExitSceneError = 3;
// The cap of Option "trace" "maxdepth" (core/scene/builder/scene_builder_ray_tracing.cpp).
constexpr int kMaxTraceDepth = 100;

// Two perfect mirrors facing each other across an orthographic camera looking along +z: every
// camera ray bounces between them until the depth cap ends it.
std::string facing_mirrors_rib(long long maxdepth) {
  return "Display \"mirrors.exr\" \"file\" \"rgba\"\n"
         "Format 2 2 1\n"
         "PixelSamples 1 1\n"
         "Option \"trace\" \"int maxdepth\" [" +
         std::to_string(maxdepth) +
         "]\n"
         "WorldBegin\n"
         "  Surface \"mirror\" \"Ks\" [0]\n"
         "  Polygon \"P\" [-10 -10 1  10 -10 1  10 10 1  -10 10 1]\n"
         "  Polygon \"P\" [-10 -10 -1  10 -10 -1  10 10 -1  -10 10 -1]\n"
         "WorldEnd\n";
}

TEST(CliParameterLimits, ADeepMaxdepthIsClampedAndFacingMirrorsStillRender) {
  ScratchDir dir("maxdepth");
  write_file(dir / "scene.rib", facing_mirrors_rib(1000000));  // crashed the renderer before the cap
  for (const char* hider : {"distance", "stochastic"}) {
    SCOPED_TRACE(hider);
    RunResult r = run_darc(dir.path(), std::string("--hider ") + hider + " --stats stats.json scene.rib");
    ASSERT_EQ(r.exit_code, kExitOk) << r.err;
    EXPECT_NE(r.err.find("scene.rib:4:1: warning: Option: Option \"trace\" \"maxdepth\" 1000000 is deeper than darc "
                         "traces: clamped to 100"),
              std::string::npos)
        << r.err;
    const nlohmann::json c = nlohmann::json::parse(read_text_file(dir / "stats.json"))["frames"][0]["counters"];
    EXPECT_EQ(c["primary_rays"], 4);
    EXPECT_EQ(c["secondary_by_kind"]["reflection"]["traced"], 4 * kMaxTraceDepth)
        << "each camera ray bounces exactly up to the cap";
  }
}

TEST(CliParameterLimits, ACropWindowWithoutAPixelIsASceneErrorAndTheWholeImageIsWritten) {
  ScratchDir dir("crop-no-pixel");
  write_file(dir / "scene.rib",
             "Display \"crop.exr\" \"file\" \"rgba\"\n"
             "Format 10 10 1\n"
             "CropWindow 0.01 0.02 0.01 0.02\n"
             "WorldBegin\n"
             "  Sphere 1 -1 1 360\n"
             "WorldEnd\n");
  RunResult r = run_darc(dir.path(), "scene.rib");
  EXPECT_EQ(r.exit_code, kExitSceneError) << r.err << " (was an I/O error, exit 1: an empty image)";
  EXPECT_NE(r.err.find("scene.rib:3:1: error: CropWindow: [0.01 0.02 0.01 0.02] keeps no pixel of the 10x10 image"),
            std::string::npos)
      << r.err;
  Pixels p;
  ASSERT_TRUE(read_image(dir / "crop.exr", p));
  EXPECT_EQ(p.width, 10);
  EXPECT_EQ(p.height, 10);
}

TEST(CliParameterLimits, TheExtremeFrameNumbersNameTheirFilesAndAreSelected) {
  ScratchDir dir("frame-numbers");
  write_file(dir / "scene.rib", tiny_frame_rib(-2147483647 - 1, "f####.exr", "rgba", 4, 3) +
                                    tiny_frame_rib(2147483647, "f####.exr", "rgba", 4, 3));
  RunResult r = run_darc(dir.path(), "--frames -2147483648-2147483647 scene.rib");
  ASSERT_EQ(r.exit_code, kExitOk) << r.err;
  EXPECT_TRUE(fs::exists(dir / "f-2147483648.exr")) << "the minus sign and every digit of INT_MIN";
  EXPECT_TRUE(fs::exists(dir / "f2147483647.exr"));
}

}  // namespace
}  // namespace darc::test
