// End-to-end: an image write that would leave less than the disk reserve free is refused: an
// error naming the file, exit 1, and no file (not even a temporary one) left behind.
#include "support/darc_command.h"
#include "support/test_frames.h"

namespace darc::test {
namespace {

constexpr int kExitOk = 0;
constexpr int kExitRenderError = 1;
constexpr int kExitUsage = 2;

// A reserve larger than any disk: every write must be refused.
TEST(CliDiskReserve, AWriteThatWouldEatTheReserveIsRefusedWithNoFileLeft) {
  ScratchDir dir("disk-reserve");
  write_file(dir / "scene.rib", tiny_frame_rib(1, "out.exr") + tiny_frame_rib(2, "two.exr"));
  RunResult r = run_darc(dir.path(), "--disk-reserve 1000000T --preview preview.png scene.rib");
  EXPECT_EQ(r.exit_code, kExitRenderError) << r.err;
  EXPECT_NE(r.err.find("darc: error: cannot write out.exr: out.exr: writing it (up to "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("less than the disk reserve of 1024000000.0 GB"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("(--disk-reserve)"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("cannot write two.exr"), std::string::npos) << "every frame is checked: " << r.err;
  EXPECT_NE(r.err.find("cannot write preview.png"), std::string::npos) << "previews too: " << r.err;
  EXPECT_FALSE(fs::exists(dir / "out.exr"));
  EXPECT_FALSE(fs::exists(dir / "two.exr"));
  EXPECT_FALSE(fs::exists(dir / "preview.png"));
  EXPECT_FALSE(has_temp_files(dir.path()));
  // With no reserve (0) and with the default, the same run writes.
  for (const char* reserve : {"--disk-reserve 0", ""}) {
    SCOPED_TRACE(reserve);
    RunResult ok = run_darc(dir.path(), std::string(reserve) + " scene.rib");
    EXPECT_EQ(ok.exit_code, kExitOk) << ok.err;
    EXPECT_TRUE(fs::exists(dir / "out.exr"));
    fs::remove(dir / "out.exr");
  }
}

TEST(CliDiskReserve, AMalformedReserveIsAUsageError) {
  ScratchDir dir("disk-reserve-usage");
  write_file(dir / "scene.rib", tiny_frame_rib(1, "out.exr"));
  for (const char* value : {"lots", "-1G", "5X"}) {
    SCOPED_TRACE(value);
    RunResult r = run_darc(dir.path(), std::string("--disk-reserve ") + value + " scene.rib");
    EXPECT_EQ(r.exit_code, kExitUsage) << r.err;
    EXPECT_FALSE(fs::exists(dir / "out.exr"));
  }
}

}  // namespace
}  // namespace darc::test
