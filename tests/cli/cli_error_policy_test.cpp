// End-to-end: the error policy. Under RI ErrorHandler "print" (the default) a request with an
// error is reported with its position and skipped, its frame is rendered from the rest and
// records the errors in its image (darc:errors, darc:first_error), the run exits 3; printing is
// capped; --skip-existing renders a frame that recorded errors again. "abort" and --strict stop
// at the first error and write nothing for its frame; "ignore" prints nothing.
#include <chrono>
#include <optional>

#include "support/darc_command.h"
#include "support/image_files.h"
#include "support/test_frames.h"

namespace darc::test {
namespace {

constexpr int kExitOk = 0;
constexpr int kExitSceneError = 3;

// `text` with the first `from` replaced by `to` (which must be there).
std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

size_t count_lines_containing(const std::string& text, const std::string& part) {
  size_t n = 0, begin = 0;
  while (begin < text.size()) {
    size_t end = text.find('\n', begin);
    if (end == std::string::npos) end = text.size();
    if (text.substr(begin, end - begin).find(part) != std::string::npos) ++n;
    begin = end + 1;
  }
  return n;
}

TEST(CliErrorPolicy, ErrorOutsideTheWorldRendersTheFrameRecordsTheErrorAndExitsThree) {
  ScratchDir dir("policy-outside");
  // Line 5 of the tiny frame is its Projection.
  write_file(dir / "scene.rib", replaced(tiny_frame_rib(1, "out.exr"), "[40]", "[200]"));
  RunResult r = run_darc(dir.path(), "scene.rib");
  EXPECT_EQ(r.exit_code, kExitSceneError) << r.err;
  const std::string first = "scene.rib:5:1: error: Projection: fov must be in (0, 180) degrees, found 200";
  EXPECT_NE(r.err.find(first), std::string::npos) << r.err;
  const std::optional<OIIO::ImageSpec> header = read_image_header(dir / "out.exr");
  ASSERT_TRUE(header) << "the frame is rendered with the rest of the scene";
  EXPECT_EQ(header->get_int_attribute("darc:errors"), 1);
  EXPECT_EQ(header->get_string_attribute("darc:first_error"), first);
}

TEST(CliErrorPolicy, ErrorInsideTheWorldSkipsOnlyItsRequest) {
  ScratchDir dir("policy-inside");
  write_file(dir / "scene.rib",
             "Display \"out.exr\" \"file\" \"rgba\"\n"
             "Format 32 24 1\n"
             "PixelSamples 1 1\n"
             "Projection \"perspective\" \"fov\" [40]\n"
             "Translate 0 0 5\n"
             "WorldBegin\n"
             "  Basis \"bsline\" 1 \"bsline\" 1\n"
             "  Surface \"constant\"\n"
             "  Color [0.2 0.4 0.9]\n"
             "  Sphere 0.5 -0.5 0.5 360\n"
             "WorldEnd\n");
  RunResult r = run_darc(dir.path(), "scene.rib");
  EXPECT_EQ(r.exit_code, kExitSceneError) << r.err;
  Pixels image;
  ASSERT_TRUE(read_image(dir / "out.exr", image)) << "the frame is rendered";
  ASSERT_EQ(image.channels, 4);
  // The sphere after the bad Basis is drawn: its constant colour fills the middle of the image.
  const float expected[4] = {0.2f, 0.4f, 0.9f, 1.0f};
  for (int c = 0; c < 4; ++c) EXPECT_NEAR(image.at(16, 12, c), expected[c], 0.01f) << "channel " << c;
  const std::optional<OIIO::ImageSpec> header = read_image_header(dir / "out.exr");
  ASSERT_TRUE(header);
  EXPECT_EQ(header->get_int_attribute("darc:errors"), 1);
  EXPECT_EQ(header->get_string_attribute("darc:first_error"), "scene.rib:7:3: error: Basis: unknown basis \"bsline\"");
}

TEST(CliErrorPolicy, AHundredThousandRepeatsPrintTheCapAndOneSummaryAndCountExactly) {
  ScratchDir dir("policy-caps");
  const int repeats = 100000;
  std::string bad;
  for (int i = 0; i < repeats; ++i) bad += "Sides 3\n";
  write_file(dir / "scene.rib", replaced(tiny_frame_rib(1, "out.exr"), "WorldBegin\n", "WorldBegin\n" + bad));
  RunResult r = run_darc(dir.path(), "scene.rib");
  EXPECT_EQ(r.exit_code, kExitSceneError);
  EXPECT_EQ(count_lines_containing(r.err, ": error: Sides: "), 20u) << "20 per kind";
  EXPECT_EQ(count_lines_containing(r.err, "darc: 99980 more errors not shown (limit 20 per kind, 200 in total)"), 1u)
      << r.err;
  EXPECT_LT(r.err.size(), 4096u) << "a screenful, not a line per error";
  const std::optional<OIIO::ImageSpec> header = read_image_header(dir / "out.exr");
  ASSERT_TRUE(header);
  EXPECT_EQ(header->get_int_attribute("darc:errors"), repeats) << "counting is not capped";
}

TEST(CliErrorPolicy, SkipExistingRendersAFrameWithErrorsAgainAndKeepsACleanOne) {
  ScratchDir dir("policy-skip");
  const std::string clean = tiny_frame_rib(1, "f#.exr") + tiny_frame_rib(2, "f#.exr");
  write_file(dir / "bad.rib", tiny_frame_rib(1, "f#.exr") + replaced(tiny_frame_rib(2, "f#.exr"), "[40]", "[200]"));
  write_file(dir / "fixed.rib", clean);
  ASSERT_EQ(run_darc(dir.path(), "bad.rib").exit_code, kExitSceneError);
  ASSERT_EQ(read_image_header(dir / "f2.exr")->get_int_attribute("darc:errors"), 1);
  // Back-date both frames so that a rewrite shows in its mtime without sleeping.
  const fs::file_time_type old_time = fs::last_write_time(dir / "f1.exr") - std::chrono::hours(1);
  fs::last_write_time(dir / "f1.exr", old_time);
  fs::last_write_time(dir / "f2.exr", old_time);

  RunOptions verbose;
  verbose.quiet = false;
  RunResult r = run_darc(dir.path(), "--skip-existing fixed.rib", verbose);
  EXPECT_EQ(r.exit_code, kExitOk) << r.err;
  EXPECT_EQ(fs::last_write_time(dir / "f1.exr"), old_time) << "the clean frame is kept";
  EXPECT_NE(fs::last_write_time(dir / "f2.exr"), old_time) << "the frame with errors is rendered again";
  EXPECT_NE(r.err.find("f2.exr exists but records errors: frame 2 rendered again"), std::string::npos) << r.err;
  EXPECT_EQ(read_image_header(dir / "f2.exr")->find_attribute("darc:errors"), nullptr);
}

// `prefix` (one line) and three tiny frames (14 lines each) f1..f3; frame 2 has a bad Projection
// (line 5 of its frame).
std::string three_frames_with_an_error_in_frame_two(const std::string& prefix) {
  return prefix + tiny_frame_rib(1, "f#.exr") + replaced(tiny_frame_rib(2, "f#.exr"), "[40]", "[200]") +
         tiny_frame_rib(3, "f#.exr");
}

TEST(CliErrorPolicy, AbortStopsAtTheFirstErrorAndWritesNothingForItsFrame) {
  ScratchDir dir("policy-abort");
  write_file(dir / "scene.rib", three_frames_with_an_error_in_frame_two("ErrorHandler \"abort\"\n"));
  RunResult r = run_darc(dir.path(), "scene.rib");
  EXPECT_EQ(r.exit_code, kExitSceneError) << r.err;
  EXPECT_NE(r.err.find("error: Projection: fov must be in"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("darc: stopped at the first error (ErrorHandler \"abort\")"), std::string::npos) << r.err;
  EXPECT_TRUE(fs::exists(dir / "f1.exr")) << "frame 1 was finished before the error";
  EXPECT_FALSE(fs::exists(dir / "f2.exr")) << "nothing is written for the frame with the error";
  EXPECT_FALSE(fs::exists(dir / "f3.exr")) << "the run stops";
  EXPECT_FALSE(has_temp_files(dir.path()));
}

TEST(CliErrorPolicy, StrictIsAbortAndOverridesTheRib) {
  ScratchDir dir("policy-strict");
  write_file(dir / "scene.rib", three_frames_with_an_error_in_frame_two("ErrorHandler \"ignore\"\n"));
  RunResult r = run_darc(dir.path(), "--strict scene.rib");
  EXPECT_EQ(r.exit_code, kExitSceneError) << r.err;
  EXPECT_NE(r.err.find("error: Projection: fov must be in"), std::string::npos) << "--strict overrides \"ignore\"";
  EXPECT_NE(r.err.find("darc: stopped at the first error (--strict)"), std::string::npos) << r.err;
  EXPECT_TRUE(fs::exists(dir / "f1.exr"));
  EXPECT_FALSE(fs::exists(dir / "f2.exr"));
  EXPECT_FALSE(fs::exists(dir / "f3.exr"));
}

TEST(CliErrorPolicy, IgnorePrintsNothingButStillCountsAndRecords) {
  ScratchDir dir("policy-ignore");
  write_file(dir / "scene.rib", three_frames_with_an_error_in_frame_two("ErrorHandler \"ignore\"\n"));
  RunResult r = run_darc(dir.path(), "scene.rib");
  EXPECT_EQ(r.exit_code, kExitSceneError) << "an ignored error still fails the run";
  EXPECT_EQ(r.err, "") << "nothing on stderr";
  const std::optional<OIIO::ImageSpec> f2 = read_image_header(dir / "f2.exr");
  ASSERT_TRUE(f2);
  EXPECT_EQ(f2->get_int_attribute("darc:errors"), 1);
  EXPECT_EQ(f2->get_string_attribute("darc:first_error"),
            "scene.rib:" + std::to_string(1 + 14 + 5) + ":1: error: Projection: fov must be in (0, 180) degrees, found "
            "200");
  for (const char* clean : {"f1.exr", "f3.exr"}) {
    const std::optional<OIIO::ImageSpec> h = read_image_header(dir / clean);
    ASSERT_TRUE(h) << clean;
    EXPECT_EQ(h->find_attribute("darc:errors"), nullptr) << clean;
  }
}

}  // namespace
}  // namespace darc::test
