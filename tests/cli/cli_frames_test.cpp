// End-to-end: where darc writes its frames and which frames it renders (-o and its '#' / %04d
// patterns, --frames, --skip-existing), and where the RIB comes from (a file, '-' for standard
// input, and --cat's output read back).
#include <chrono>

#include "support/darc_command.h"
#include "support/image_files.h"
#include "support/test_frames.h"

namespace darc::test {
namespace {

// A sequence of `count` tiny frames numbered 1..count, each with the Display name `display`.
std::string sequence_rib(int count, const std::string& display) {
  std::string rib;
  for (int frame = 1; frame <= count; ++frame) rib += tiny_frame_rib(frame, display);
  return rib;
}

// The image files (not the scene, not the captured streams) in `dir`.
std::vector<std::string> images_in(const fs::path& dir) {
  std::vector<std::string> images;
  for (const std::string& n : file_names(dir))
    if (n.ends_with(".exr") || n.ends_with(".png") || n.ends_with(".tif")) images.push_back(n);
  return images;
}

using Names = std::vector<std::string>;

TEST(CliFrames, OutputOptionOverridesDisplay) {
  ScratchDir dir("output-override");
  write_file(dir / "scene.rib", tiny_frame_rib(1, "display.exr"));
  RunResult r = run_darc(dir.path(), "-o out.exr scene.rib");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(images_in(dir.path()), Names{"out.exr"});
}

TEST(CliFrames, HashRunTakesTheZeroPaddedFrameNumber) {
  ScratchDir dir("hash-pattern");
  write_file(dir / "seq.rib", sequence_rib(3, "display.exr"));
  RunResult r = run_darc(dir.path(), "-o 'h###.tif' seq.rib");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(images_in(dir.path()), (Names{"h001.tif", "h002.tif", "h003.tif"}));
}

TEST(CliFrames, PrintfPatternTakesTheZeroPaddedFrameNumber) {
  ScratchDir dir("printf-pattern");
  write_file(dir / "seq.rib", sequence_rib(2, "display.exr"));
  RunResult r = run_darc(dir.path(), "-o 'p%04d.png' seq.rib");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(images_in(dir.path()), (Names{"p0001.png", "p0002.png"}));
}

TEST(CliFrames, FrameListRendersExactlyTheListedFrames) {
  ScratchDir dir("frame-list");
  write_file(dir / "seq.rib", sequence_rib(6, "f#.exr"));
  RunResult r = run_darc(dir.path(), "--frames 2,4-5 seq.rib");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(images_in(dir.path()), (Names{"f2.exr", "f4.exr", "f5.exr"}));
}

TEST(CliFrames, FrameListSelectingNothingWarns) {
  ScratchDir dir("frame-list-empty");
  write_file(dir / "seq.rib", sequence_rib(2, "f#.exr"));
  RunResult r = run_darc(dir.path(), "--frames 7 seq.rib");
  EXPECT_EQ(r.exit_code, 0) << "a warning never fails the run: " << r.err;
  EXPECT_NE(r.err.find("warning: --frames"), std::string::npos) << r.err;
  EXPECT_TRUE(images_in(dir.path()).empty());
}

TEST(CliFrames, SkipExistingKeepsReadableFramesAndRendersTheOthers) {
  ScratchDir dir("skip-existing");
  write_file(dir / "seq.rib", sequence_rib(3, "f#.exr"));
  ASSERT_EQ(run_darc(dir.path(), "--frames 1 seq.rib").exit_code, 0);
  // Back-date frame 1 so that a rewrite would show in its mtime without sleeping; frame 3 exists
  // but does not open as an image (an interrupted copy), so it must be rendered again.
  const fs::file_time_type old_time = fs::last_write_time(dir / "f1.exr") - std::chrono::hours(1);
  fs::last_write_time(dir / "f1.exr", old_time);
  write_file(dir / "f3.exr", "not an image");

  RunResult r = run_darc(dir.path(), "--skip-existing seq.rib");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(fs::last_write_time(dir / "f1.exr"), old_time) << "frame 1 exists and must be skipped";
  Pixels f2, f3;
  EXPECT_TRUE(read_image(dir / "f2.exr", f2)) << "frame 2 was missing and must be rendered";
  EXPECT_TRUE(read_image(dir / "f3.exr", f3)) << "frame 3 did not open and must be rendered again";
}

TEST(CliFrames, StandardInputRendersLikeAFile) {
  ScratchDir dir("stdin");
  write_file(dir / "scene.rib", tiny_frame_rib(1, "out.exr"));
  RunOptions from_stdin;
  from_stdin.stdin_file = dir / "scene.rib";
  RunResult piped = run_darc(dir.path(), "-o piped.exr -", from_stdin);
  ASSERT_EQ(piped.exit_code, 0) << piped.err;
  ASSERT_EQ(run_darc(dir.path(), "-o file.exr scene.rib").exit_code, 0);
  Pixels a, b;
  ASSERT_TRUE(read_image(dir / "piped.exr", a));
  ASSERT_TRUE(read_image(dir / "file.exr", b));
  EXPECT_TRUE(a.identical_to(b));
}

TEST(CliFrames, StandardInputErrorsNameStdin) {
  ScratchDir dir("stdin-error");
  write_file(dir / "bad.rib", "WorldBegin\nSphere 1 -1 1 360\n");  // WorldEnd missing
  RunOptions from_stdin;
  from_stdin.stdin_file = dir / "bad.rib";
  RunResult r = run_darc(dir.path(), "-", from_stdin);
  EXPECT_EQ(r.exit_code, 3) << r.err;
  EXPECT_NE(r.err.find("<stdin>:"), std::string::npos) << r.err;
}

// A scene that exercises what RibWriter must carry over: options before the frame, nested
// transforms and attributes, a light, a varying-width curve, a polygon, and numbers that need
// every digit.
std::string cat_scene_rib() {
  return "Format 40 30 1\n"
         "PixelSamples 2 2\n"
         "Display \"ref.exr\" \"file\" \"rgba\"\n"
         "Projection \"perspective\" \"fov\" [37.123456789]\n"
         "Translate 0.1 -0.05 5.000001\n"
         "Rotate 12.5 0 1 0\n"
         "WorldBegin\n"
         "  LightSource \"distantlight\" 1 \"intensity\" [1.25] \"from\" [0 0 -1] \"to\" [0.3 -0.2 1]\n"
         "  AttributeBegin\n"
         "    Surface \"plastic\" \"Ks\" [0.4] \"roughness\" [0.07]\n"
         "    Color [0.9 0.3 0.1]\n"
         "    Scale 1.1 0.9 1\n"
         "    Curves \"cubic\" [4] \"nonperiodic\" \"P\" [-1 -1 0  -0.3 0.5 -0.5  0.3 -0.5 -0.5  1 1 0]"
         " \"width\" [0.12 0.0300001]\n"
         "  AttributeEnd\n"
         "  TransformBegin\n"
         "    Translate 0 0 1\n"
         "    Surface \"matte\"\n"
         "    Polygon \"P\" [-2 -2 0  2 -2 0  2 2 0  -2 2 0]\n"
         "  TransformEnd\n"
         "  Sphere 0.3333333333 -0.3333333333 0.3333333333 360\n"
         "WorldEnd\n";
}

TEST(CliFrames, CatPrintsRibThatRendersTheSameImage) {
  ScratchDir dir("cat");
  write_file(dir / "scene.rib", cat_scene_rib());
  RunResult cat = run_darc(dir.path(), "--cat scene.rib");
  ASSERT_EQ(cat.exit_code, 0) << cat.err;
  ASSERT_FALSE(cat.out.empty());
  EXPECT_FALSE(fs::exists(dir / "ref.exr")) << "--cat prints, it does not render";
  write_file(dir / "cat.rib", cat.out);
  ASSERT_EQ(run_darc(dir.path(), "-o original.exr scene.rib").exit_code, 0);
  RunResult again = run_darc(dir.path(), "-o printed.exr cat.rib");
  ASSERT_EQ(again.exit_code, 0) << again.err << "\n" << cat.out;
  Pixels a, b;
  ASSERT_TRUE(read_image(dir / "original.exr", a));
  ASSERT_TRUE(read_image(dir / "printed.exr", b));
  EXPECT_TRUE(a.identical_to(b)) << "--cat output:\n" << cat.out;
}

}  // namespace
}  // namespace darc::test
