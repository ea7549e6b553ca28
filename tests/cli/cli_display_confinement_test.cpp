// End-to-end: where a RIB's Display may write. Inside the working folder (a subfolder too) as
// given; an absolute name, a ".." out or a linked folder is a scene error at the Display, and
// the frame is written to the name's last component in the working folder, nothing outside.
// -o is the user's and never restricted; --trust-rib lifts the rule.
#include "support/darc_command.h"
#include "support/image_files.h"
#include "support/test_frames.h"

namespace darc::test {
namespace {

constexpr int kExitOk = 0;
constexpr int kExitSceneError = 3;

TEST(CliDisplayConfinement, ANameOutsideTheWorkingFolderIsRefusedAndWrittenInside) {
  ScratchDir dir("display-out");
  fs::create_directories(dir / "work");
  fs::create_directories(dir / "elsewhere");
  fs::create_directory_symlink(dir / "elsewhere", dir / "work/link");
  const fs::path work = dir / "work";
  for (const std::string& name :
       std::vector<std::string>{(dir / "elsewhere/shot.exr").string(), "../elsewhere/shot.exr", "link/shot.exr"}) {
    SCOPED_TRACE(name);
    write_file(work / "scene.rib", tiny_frame_rib(1, name));
    RunResult r = run_darc(work, "scene.rib");
    EXPECT_EQ(r.exit_code, kExitSceneError) << r.err;
    EXPECT_NE(r.err.find("scene.rib:2:1: error: Display: Display name \"" + name + "\" refused: "), std::string::npos)
        << r.err;
    EXPECT_FALSE(fs::exists(dir / "elsewhere/shot.exr")) << "nothing written outside";
    EXPECT_TRUE(fs::exists(work / "shot.exr")) << "the frame is in the working folder";
    const std::optional<OIIO::ImageSpec> header = read_image_header(work / "shot.exr");
    ASSERT_TRUE(header);
    EXPECT_EQ(header->get_int_attribute("darc:errors"), 1);
    fs::remove(work / "shot.exr");
  }
}

TEST(CliDisplayConfinement, OutputAndTrustRibAreTheUsersChoice) {
  ScratchDir dir("display-choice");
  fs::create_directories(dir / "work");
  fs::create_directories(dir / "elsewhere");
  const fs::path work = dir / "work";
  const std::string outside = (dir / "elsewhere/shot.exr").string();
  write_file(work / "scene.rib", tiny_frame_rib(1, outside));
  RunResult o = run_darc(work, "-o '" + (dir / "elsewhere/chosen.exr").string() + "' scene.rib");
  EXPECT_EQ(o.exit_code, kExitOk) << o.err;
  EXPECT_TRUE(fs::exists(dir / "elsewhere/chosen.exr"));
  RunResult trusted = run_darc(work, "--trust-rib scene.rib");
  EXPECT_EQ(trusted.exit_code, kExitOk) << trusted.err;
  EXPECT_TRUE(fs::exists(outside));
  // A subfolder of the working folder is inside.
  write_file(work / "sub.rib", tiny_frame_rib(1, "renders/shot.exr"));
  fs::create_directories(work / "renders");
  RunResult sub = run_darc(work, "sub.rib");
  EXPECT_EQ(sub.exit_code, kExitOk) << sub.err;
  EXPECT_TRUE(fs::exists(work / "renders/shot.exr"));
}

}  // namespace
}  // namespace darc::test
