// End-to-end: a frame whose every primitive darc skips still renders (an empty image, exit code
// 0: nothing in it is an error), but darc says so on stderr instead of writing black silently.
#include "support/darc_command.h"

namespace darc::test {
namespace {

TEST(Cli, AFrameOfUnsupportedPrimitivesWarnsNothingRenderableAndExitsZero) {
  ScratchDir dir("nothing-renderable");
  write_file(dir / "scene.rib", R"RIB(FrameBegin 3
Display "out.exr" "file" "rgba"
Format 16 12 1
PixelSamples 1 1
Projection "perspective" "fov" [40]
Translate 0 0 5
WorldBegin
  Geometry "teapot"
  Blobby 1 [1001 0] [1 0 0 0 0 1 0 0 0 0 1 0 0 0 0 1] [""]
WorldEnd
FrameEnd
)RIB");
  RunResult r = run_darc(dir.path(), "scene.rib");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("scene.rib:10:1: warning: WorldEnd: nothing renderable in frame 3: every primitive in it is "
                       "of a kind darc does not support (Blobby, Geometry)"),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("scene.rib:8:3: warning: Geometry: request \"Geometry\" (RI Spec 3.2) is not "
                       "supported: skipped"),
            std::string::npos)
      << r.err;
  EXPECT_TRUE(fs::exists(dir / "out.exr")) << "the frame is still written";
}

}  // namespace
}  // namespace darc::test
