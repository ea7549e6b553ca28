// End-to-end: the options that change how a frame is rendered (--res, --pixel-samples, --hider,
// --seed, --threads), the --stats JSON, and the progress log.
#include <cmath>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>

#include "support/darc_command.h"
#include "support/image_compare.h"
#include "support/image_files.h"
#include "support/test_frames.h"

namespace darc::test {
namespace {

// Progress on a non-terminal stderr is one line per 10 %: 0 %, 10 %, ... 100 % at most.
constexpr int kMaxProgressLinesPerFrame = 11;
// A render of the tiny scene takes milliseconds; anything near this means a broken clock.
constexpr double kSaneSecondsBound = 60.0;

// `rib_name` in `dir` rendered with `args` to `out`, read back (no pixels when that fails, which
// fails the test).
Pixels render(const ScratchDir& dir, const std::string& rib_name, const std::string& args, const std::string& out) {
  const FileRender f = render_file(dir, rib_name, args + " -o " + out, out);
  EXPECT_TRUE(rendered_cleanly(f)) << out;
  return f.image.value_or(Pixels{});
}

TEST(CliRenderOptions, ResOverridesFormat) {
  ScratchDir dir("res");
  write_file(dir / "scene.rib", tiny_frame_rib(1, "out.exr", "rgba", 32, 24));
  Pixels p = render(dir, "scene.rib", "--res 64x48", "res.exr");
  EXPECT_EQ(p.width, 64);
  EXPECT_EQ(p.height, 48);
}

TEST(CliRenderOptions, StatsHoldOneEntryPerFrameWithSaneCounters) {
  ScratchDir dir("stats");
  constexpr int kWidth = 20, kHeight = 10, kSamples = 3;
  write_file(dir / "seq.rib", tiny_frame_rib(1, "f#.exr") + tiny_frame_rib(2, "f#.exr"));
  RunResult r = run_darc(dir.path(), "--res 20x10 --pixel-samples 3 --stats stats.json seq.rib");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  nlohmann::json stats;
  ASSERT_NO_THROW(stats = nlohmann::json::parse(read_text_file(dir / "stats.json")));
  ASSERT_TRUE(stats["frames"].is_array());
  ASSERT_EQ(stats["frames"].size(), 2u);
  for (int i = 0; i < 2; ++i) {
    const nlohmann::json& f = stats["frames"][i];
    SCOPED_TRACE("frame entry " + std::to_string(i));
    EXPECT_EQ(f["frame"], i + 1);
    EXPECT_EQ(f["output"], "f" + std::to_string(i + 1) + ".exr");
    EXPECT_EQ(f["resolution"], (nlohmann::json{kWidth, kHeight}));
    for (const char* key : {"parse_seconds", "build_seconds", "render_seconds"}) {
      ASSERT_TRUE(f[key].is_number()) << key;
      const double seconds = f[key].get<double>();
      EXPECT_TRUE(std::isfinite(seconds) && seconds >= 0 && seconds < kSaneSecondsBound) << key << " = " << seconds;
    }
    const nlohmann::json& c = f["counters"];
    // The distance hider traces exactly one primary ray per pixel sample.
    EXPECT_EQ(c["primary_rays"], kWidth * kHeight * kSamples * kSamples);
    // The curve crosses the frame, so some rays test its segments.
    EXPECT_GT(c["curve_segment_tests"].get<long long>(), 0);
    EXPECT_GE(c["rays_pruned_by_contribution"].get<long long>(), 0);
    // The curve passes in front of the opaque sphere: some ray keeps both fragments, and no ray
    // more (one fragment per strand; the sphere's front hit ends the ray).
    EXPECT_EQ(c["peak_abuffer_length"], 2);
  }
}

// "--stats s.####.json": one file per rendered frame, each holding that frame's entry alone, so
// that the frames of a sequence (a farm's tasks) each leave their own record.
TEST(CliRenderOptions, StatsWithAFramePatternWriteOneFilePerFrame) {
  ScratchDir dir("stats-per-frame");
  write_file(dir / "seq.rib", tiny_frame_rib(1, "f#.exr") + tiny_frame_rib(2, "f#.exr") + tiny_frame_rib(3, "f#.exr"));
  RunResult r = run_darc(dir.path(), "--frames 1,3 --stats s.####.json seq.rib");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(file_names(dir.path()), (std::vector<std::string>{"f1.exr", "f3.exr", "s.0001.json", "s.0003.json",
                                                               "seq.rib", "stderr.txt", "stdout.txt"}))
      << "frame 2 is not selected; no temporary file is left";
  for (int frame : {1, 3}) {
    SCOPED_TRACE("frame " + std::to_string(frame));
    nlohmann::json stats;
    ASSERT_NO_THROW(stats = nlohmann::json::parse(read_text_file(dir / ("s.000" + std::to_string(frame) + ".json"))));
    ASSERT_EQ(stats["frames"].size(), 1u);
    EXPECT_EQ(stats["frames"][0]["frame"], frame);
    EXPECT_EQ(stats["frames"][0]["output"], "f" + std::to_string(frame) + ".exr");
  }
}

// A frame --skip-existing skips is not rendered, so it writes no stats: the file of the run that
// rendered it is kept as it was (here: removed, and not written again).
TEST(CliRenderOptions, SkippedFramesWriteNoPerFrameStats) {
  ScratchDir dir("stats-skip");
  write_file(dir / "seq.rib", tiny_frame_rib(1, "f#.exr") + tiny_frame_rib(2, "f#.exr"));
  ASSERT_EQ(run_darc(dir.path(), "--stats s.#.json seq.rib").exit_code, 0);
  fs::remove(dir / "s.1.json");
  fs::remove(dir / "f2.exr");
  RunResult r = run_darc(dir.path(), "--skip-existing --stats s.#.json seq.rib");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_FALSE(fs::exists(dir / "s.1.json")) << "frame 1 was skipped";
  EXPECT_TRUE(fs::exists(dir / "s.2.json")) << "frame 2 was rendered again";
}

TEST(CliRenderOptions, PixelSamplesOverridesPixelSamples) {
  ScratchDir dir("pixel-samples");
  write_file(dir / "scene.rib", tiny_frame_rib(1, "out.exr"));
  ASSERT_EQ(run_darc(dir.path(), "--hider stochastic --pixel-samples 4 --stats stats.json scene.rib").exit_code, 0);
  nlohmann::json f = nlohmann::json::parse(read_text_file(dir / "stats.json"))["frames"][0];
  EXPECT_EQ(f["pixel_samples"], (nlohmann::json{4, 4}));
  EXPECT_EQ(f["counters"]["primary_rays"], 32 * 24 * 16) << "the stochastic hider traces N x N rays per pixel";
}

TEST(CliRenderOptions, BothHidersRenderTheSameScene) {
  ScratchDir dir("hiders");
  write_file(dir / "scene.rib", tiny_frame_rib(1, "out.exr"));
  Pixels distance = render(dir, "scene.rib", "--hider distance", "distance.exr");
  Pixels stochastic = render(dir, "scene.rib", "--hider stochastic --pixel-samples 4", "stochastic.exr");
  ASSERT_EQ(distance.v.size(), stochastic.v.size());
  // The sphere's centre is solid blue in both; they differ only along edges.
  EXPECT_NEAR(distance.at(16, 12, 2), 0.9f, 1e-3f);
  EXPECT_NEAR(stochastic.at(16, 12, 2), 0.9f, 1e-3f);
  EXPECT_LT(compare(distance, stochastic).mean_abs, 0.05);
}

TEST(CliRenderOptions, SeedChangesStochasticSamplesAndNotTheDistanceHider) {
  ScratchDir dir("seed");
  write_file(dir / "scene.rib", tiny_frame_rib(1, "out.exr"));
  Pixels s1 = render(dir, "scene.rib", "--hider stochastic --pixel-samples 2 --seed 1", "s1.exr");
  Pixels s2 = render(dir, "scene.rib", "--hider stochastic --pixel-samples 2 --seed 2", "s2.exr");
  EXPECT_FALSE(s1.identical_to(s2)) << "jittered samples depend on the seed";
  EXPECT_LT(compare(s1, s2).mean_abs, 0.05) << "but only edge pixels change";
  // The distance hider at 1x1 traces the pixel centre: no randomness at all.
  Pixels d1 = render(dir, "scene.rib", "--hider distance --seed 1", "d1.exr");
  Pixels d2 = render(dir, "scene.rib", "--hider distance --seed 2", "d2.exr");
  EXPECT_TRUE(d1.identical_to(d2));
}

// Several tiles (Film tiles are 32 pixels) so that two threads really share the frame.
constexpr int kManyTilesWidth = 96, kManyTilesHeight = 64;

class ThreadCount : public ::testing::TestWithParam<const char*> {};

TEST_P(ThreadCount, OneAndTwoThreadsGiveIdenticalFiles) {
  const std::string hider = GetParam();
  ScratchDir dir("threads-" + hider);
  write_file(dir / "scene.rib", tiny_frame_rib(1, "out.exr", "rgba", kManyTilesWidth, kManyTilesHeight));
  // PNG carries no render time, so the files themselves must match byte for byte; EXR records
  // the render time in its header, so there the pixels must.
  const std::string common = "--hider " + hider + " --pixel-samples 2 ";
  ASSERT_EQ(run_darc(dir.path(), common + "--threads 1 -o t1.png --preview t1-preview.png scene.rib").exit_code, 0);
  ASSERT_EQ(run_darc(dir.path(), common + "--threads 2 -o t2.exr --preview t2-preview.png scene.rib").exit_code, 0);
  ASSERT_EQ(run_darc(dir.path(), common + "--threads 1 -o t1.exr scene.rib").exit_code, 0);
  EXPECT_EQ(read_text_file(dir / "t1-preview.png"), read_text_file(dir / "t2-preview.png"));
  EXPECT_EQ(read_text_file(dir / "t1.png"), read_text_file(dir / "t2-preview.png"));
  Pixels a, b;
  ASSERT_TRUE(read_image(dir / "t1.exr", a));
  ASSERT_TRUE(read_image(dir / "t2.exr", b));
  EXPECT_TRUE(a.identical_to(b));
}

INSTANTIATE_TEST_SUITE_P(CliRenderOptions, ThreadCount, ::testing::Values("distance", "stochastic"));

TEST(CliRenderOptions, ProgressLogHasAtMostElevenLinesPerFrame) {
  ScratchDir dir("progress");
  // 256 x 256 pixels is 64 tiles on two threads: many progress reports per frame, out of order.
  write_file(dir / "seq.rib",
             tiny_frame_rib(1, "f#.exr", "rgba", 256, 256) + tiny_frame_rib(2, "f#.exr", "rgba", 256, 256));
  RunOptions loud;
  loud.quiet = false;
  RunResult r = run_darc(dir.path(), "--threads 2 seq.rib", loud);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::map<std::string, int> lines_per_frame;
  std::istringstream err(r.err);
  for (std::string line; std::getline(err, line);) {
    const size_t colon = line.find(": ");
    if (colon != std::string::npos && line.find("% (") != std::string::npos) ++lines_per_frame[line.substr(0, colon)];
  }
  ASSERT_EQ(lines_per_frame.size(), 2u) << r.err;
  for (const auto& [frame, lines] : lines_per_frame) {
    EXPECT_GE(lines, 1) << frame;
    EXPECT_LE(lines, kMaxProgressLinesPerFrame) << frame << "\n" << r.err;
  }
  EXPECT_NE(r.err.find("f1.exr: 100%"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace darc::test
