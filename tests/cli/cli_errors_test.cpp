// End-to-end: the darc command's exit codes and error reports (DESIGN.md "Command-line
// contract": 0 ok, 1 render or I/O error, 2 usage error, 3 scene error), and that a scene error
// skips its request while its frame is still written, recording the error, and the run exits 3.
#include <nlohmann/json.hpp>
#include <regex>

#include "support/darc_command.h"
#include "support/image_files.h"
#include "support/test_frames.h"

namespace darc::test {
namespace {

constexpr int kExitOk = 0;
constexpr int kExitRenderError = 1;
constexpr int kExitUsage = 2;
constexpr int kExitSceneError = 3;

// Only the files every run leaves (the scene and the captured output streams).
bool only_inputs_and_logs(const fs::path& dir, const std::vector<std::string>& inputs) {
  for (const std::string& n : file_names(dir)) {
    if (n == "stdout.txt" || n == "stderr.txt") continue;
    if (std::find(inputs.begin(), inputs.end(), n) == inputs.end()) return false;
  }
  return true;
}

// One test for all of them: each darc launch costs a few tenths of a second of dynamic loading,
// and so does each test process.
TEST(Cli, UsageErrorsExitTwoWithAMessageAndWriteNothing) {
  ScratchDir dir("usage");
  write_file(dir / "scene.rib", tiny_frame_rib(1, "scene.exr"));
  fs::create_directory(dir / "adir");
  for (const char* args : {"--no-such-option scene.rib", "--res 10 scene.rib", "--res 10x10junk scene.rib",
                           "--frames 5-2 scene.rib", "missing.rib", "adir", "--hider foo scene.rib"}) {
    SCOPED_TRACE(args);
    RunResult r = run_darc(dir.path(), args);
    EXPECT_EQ(r.exit_code, kExitUsage) << r.err;
    EXPECT_FALSE(r.err.empty()) << "a usage error says what is wrong";
    EXPECT_FALSE(fs::exists(dir / "scene.exr")) << "nothing is rendered after a usage error";
  }
}

TEST(Cli, VersionPrintsTheVersionAndExitsZero) {
  ScratchDir dir("version");
  RunResult r = run_darc(dir.path(), "--version");
  EXPECT_EQ(r.exit_code, kExitOk) << r.err;
  EXPECT_TRUE(std::regex_search(r.out, std::regex(R"(^darc [0-9]+\.[0-9]+\.[0-9]+)"))) << r.out;
}

TEST(Cli, HelpListsTheOptionsAndExitsZero) {
  ScratchDir dir("help");
  RunResult r = run_darc(dir.path(), "--help");
  EXPECT_EQ(r.exit_code, kExitOk) << r.err;
  for (const char* option :
       {"--output", "--res", "--hider", "--frames", "--skip-existing", "--strict", "--stats", "--seed"})
    EXPECT_NE(r.out.find(option), std::string::npos) << "--help does not mention " << option;
}

TEST(Cli, MalformedRibExitsThreeWithFileLineColumnAndWritesTheFrameWithoutTheRequest) {
  ScratchDir dir("malformed");
  // Line 4: the bracket opened at column 15 is never closed before the next request.
  write_file(dir / "bad.rib",
             "Display \"bad.exr\" \"file\" \"rgba\"\n"
             "Format 32 24 1\n"
             "WorldBegin\n"
             "Sphere 1 -1 1 [360\n"
             "WorldEnd\n");
  RunResult r = run_darc(dir.path(), "bad.rib");
  EXPECT_EQ(r.exit_code, kExitSceneError) << r.err;
  EXPECT_NE(r.err.find("bad.rib:4:15:"), std::string::npos) << r.err;
  EXPECT_TRUE(only_inputs_and_logs(dir.path(), {"bad.rib", "bad.exr"})) << "the image and no temporary file";
  const std::optional<OIIO::ImageSpec> header = read_image_header(dir / "bad.exr");
  ASSERT_TRUE(header);
  EXPECT_EQ(header->get_int_attribute("darc:errors"), 1);
  const std::string first = header->get_string_attribute("darc:first_error");
  EXPECT_EQ(first.rfind("bad.rib:4:15: error: Sphere: ", 0), 0u) << first;
}

TEST(Cli, ErrorInFrameTwoOfThreeIsRecordedInFrameTwoOnly) {
  ScratchDir dir("frame-error");
  // Frame 2's curve has 2 vertices where "cubic" [4] needs 4: a validation error at line 2 of
  // that frame's world block.
  std::string frame2 = tiny_frame_rib(2, "f#.exr");
  const std::string good_curve = "\"P\" [-1 -1 0  -0.3 0.5 -0.5  0.3 -0.5 -0.5  1 1 0]";
  frame2.replace(frame2.find(good_curve), good_curve.size(), "\"P\" [0 0 0  1 1 1]");
  write_file(dir / "three.rib", tiny_frame_rib(1, "f#.exr") + frame2 + tiny_frame_rib(3, "f#.exr"));
  RunResult r = run_darc(dir.path(), "--stats stats.json three.rib");
  EXPECT_EQ(r.exit_code, kExitSceneError) << r.err;
  EXPECT_TRUE(std::regex_search(r.err, std::regex(R"(three\.rib:[0-9]+:[0-9]+: error: Curves)"))) << r.err;
  const std::optional<OIIO::ImageSpec> f1 = read_image_header(dir / "f1.exr");
  const std::optional<OIIO::ImageSpec> f2 = read_image_header(dir / "f2.exr");
  const std::optional<OIIO::ImageSpec> f3 = read_image_header(dir / "f3.exr");
  ASSERT_TRUE(f1 && f2 && f3) << "every frame is written, frame 2 without its bad curve";
  EXPECT_EQ(f2->get_int_attribute("darc:errors"), 1);
  const std::string first = f2->get_string_attribute("darc:first_error");
  EXPECT_TRUE(std::regex_search(first, std::regex(R"(^three\.rib:[0-9]+:[0-9]+: error: Curves: )"))) << first;
  for (const OIIO::ImageSpec* clean : {&*f1, &*f3}) {
    EXPECT_EQ(clean->find_attribute("darc:errors"), nullptr) << "a frame without errors records none";
    EXPECT_EQ(clean->find_attribute("darc:first_error"), nullptr);
  }
  EXPECT_FALSE(has_temp_files(dir.path()));
  nlohmann::json stats = nlohmann::json::parse(read_text_file(dir / "stats.json"));
  ASSERT_EQ(stats["frames"].size(), 3u);
  EXPECT_EQ(stats["frames"][1]["frame"], 2);
}

TEST(Cli, UnwritableOutputExitsOneAndLeavesNoTemporaryFile) {
  ScratchDir dir("unwritable");
  write_file(dir / "scene.rib", tiny_frame_rib(1, "scene.exr"));
  RunResult r = run_darc(dir.path(), "-o no-such-dir/out.exr scene.rib");
  EXPECT_EQ(r.exit_code, kExitRenderError) << r.err;
  EXPECT_NE(r.err.find("no-such-dir/out.exr"), std::string::npos) << r.err;
  EXPECT_TRUE(only_inputs_and_logs(dir.path(), {"scene.rib"}));
}

}  // namespace
}  // namespace darc::test
