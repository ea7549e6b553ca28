// A RIB's Display name stays inside the working folder unless the user trusts the RIB: an
// absolute name, a ".." that leads out, or a folder that is a symbolic link to elsewhere is an
// error at the Display request, and the frame goes to the name's last component instead.
#include "core/scene/builder/display_confinement.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>

#include "support/scenes_from_rib.h"

namespace darc {
namespace {

namespace fs = std::filesystem;

// A scratch working folder with a real subfolder and a link to a folder outside it.
class WorkingFolder {
 public:
  WorkingFolder() {
    root_ = fs::temp_directory_path() / ("darc_display_" + std::to_string(::getpid()));
    fs::remove_all(root_);
    fs::create_directories(root_ / "work/renders");
    fs::create_directories(root_ / "elsewhere");
    fs::create_directory_symlink(root_ / "elsewhere", root_ / "work/link");
    work_ = fs::canonical(root_ / "work");
  }
  ~WorkingFolder() {
    std::error_code ec;
    fs::remove_all(root_, ec);
  }
  const fs::path& work() const { return work_; }
  fs::path root() const { return fs::canonical(root_); }

 private:
  fs::path root_, work_;
};

std::vector<Diagnostic> errors(const test::Built& b) {
  std::vector<Diagnostic> out;
  for (const Diagnostic& d : b.diagnostics)
    if (d.severity == Severity::Error) out.push_back(d);
  return out;
}

TEST(DisplayConfinement, NamesInsideTheWorkingFolderAreAllowed) {
  WorkingFolder dir;
  for (const char* name : {"out.exr", "renders/out.exr", "new/folder/out.exr", "renders/../out.#.exr", "./a.tif", ""}) {
    SCOPED_TRACE(name);
    const DisplayNameCheck check = check_display_name(name, dir.work());
    EXPECT_TRUE(check.allowed) << check.reason;
  }
}

TEST(DisplayConfinement, NamesThatLeaveAreRefusedWithTheirLastComponent) {
  WorkingFolder dir;
  struct Case {
    std::string name, reason, fallback;
  };
  const std::vector<Case> cases = {
      {(dir.root() / "elsewhere/out.exr").string(), "it is an absolute path", "out.exr"},
      {"../out.exr", "its \"..\" leads out of the working folder", "out.exr"},
      {"renders/../../x.tif", "its \"..\" leads out of the working folder", "x.tif"},
      {"link/out.exr", "its folder is " + (dir.root() / "elsewhere").string() + " (through a symbolic link)",
       "out.exr"},
      {"/", "it is an absolute path", ""},
      {"renders/..", "it names a folder, not a file", ""},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    const DisplayNameCheck check = check_display_name(c.name, dir.work());
    EXPECT_FALSE(check.allowed);
    EXPECT_EQ(check.reason.rfind(c.reason, 0), 0u) << check.reason;
    EXPECT_EQ(check.fallback, c.fallback);
  }
}

TEST(DisplayConfinement, SceneBuilderReportsAtTheDisplayAndKeepsTheLastComponent) {
  WorkingFolder dir;
  FrameOverrides overrides;
  overrides.display_folder = dir.work().string();
  const test::Built b = test::build("Display \"/tmp/x/shot.exr\" \"file\" \"rgba\"\nWorldBegin\nWorldEnd\n"
                                    "Display \"../up.exr\" \"file\" \"rgb\"\nWorldBegin\nWorldEnd\n"
                                    "Display \"..\" \"file\" \"rgb\"\nWorldBegin\nWorldEnd\n",
                                    {}, overrides);
  ASSERT_EQ(b.scenes.size(), 3u);
  EXPECT_EQ(b.scenes[0].output.display_name, "shot.exr");
  EXPECT_EQ(b.scenes[1].output.display_name, "up.exr");
  EXPECT_EQ(b.scenes[1].output.display_mode, "rgb") << "the rest of the request holds";
  EXPECT_EQ(b.scenes[2].output.display_name, "up.exr") << "no last component: the name in effect";
  const std::vector<Diagnostic> refused = errors(b);
  ASSERT_EQ(refused.size(), 3u);
  EXPECT_EQ(refused[0].str(),
            "test.rib:1:1: error: Display: Display name \"/tmp/x/shot.exr\" refused: it is an absolute path; a RIB's "
            "Display name must stay inside the working folder (" +
                dir.work().string() +
                "): the frame is written to \"shot.exr\" there instead (-o names any file; --trust-rib lifts this "
                "rule)");
  EXPECT_EQ(refused[1].loc.line, 4);
  EXPECT_EQ(b.frame_errors[0].count, 1) << "the image records the error";
}

TEST(DisplayConfinement, WithoutAFolderAnyNameIsKept) {
  const test::Built b = test::build("Display \"/tmp/x/shot.exr\" \"file\" \"rgba\"\nWorldBegin\nWorldEnd\n");
  ASSERT_EQ(b.scenes.size(), 1u);
  EXPECT_EQ(b.scenes[0].output.display_name, "/tmp/x/shot.exr");
  EXPECT_TRUE(errors(b).empty());
}

}  // namespace
}  // namespace darc
