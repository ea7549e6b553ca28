// End-to-end: progress in a sequence says which frame of how many is rendering and estimates
// the whole run; frames skipped because their image exists leave the count.
#include "support/darc_command.h"
#include "support/test_frames.h"

namespace darc::test {
namespace {

TEST(CliSequenceProgress, LinesSayFrameIOfNAndTheRunsEstimate) {
  ScratchDir dir("sequence-progress");
  write_file(dir / "seq.rib", tiny_frame_rib(1, "f#.exr", "rgba", 64, 48) + tiny_frame_rib(2, "f#.exr", "rgba", 64, 48) +
                                  tiny_frame_rib(3, "f#.exr", "rgba", 64, 48));
  RunOptions loud;
  loud.quiet = false;
  RunResult r = run_darc(dir.path(), "seq.rib", loud);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (const char* part : {"frame 1/3 f1.exr: 100%", "frame 2/3 f2.exr: 100%", "frame 3/3 f3.exr: 100%", "; run ETA "})
    EXPECT_NE(r.err.find(part), std::string::npos) << part << "\n" << r.err;

  // Frame 2 exists: the run is two frames.
  fs::remove(dir / "f1.exr");
  fs::remove(dir / "f3.exr");
  r = run_darc(dir.path(), "--skip-existing --frames 1-3 seq.rib", loud);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("frame 1/3 f1.exr: 100%"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("frame 2/2 f3.exr: 100%"), std::string::npos) << r.err;
}

TEST(CliSequenceProgress, OneFrameHasNoFrameCount) {
  ScratchDir dir("single-progress");
  write_file(dir / "one.rib", tiny_frame_rib(1, "f#.exr", "rgba", 64, 48));
  RunOptions loud;
  loud.quiet = false;
  RunResult r = run_darc(dir.path(), "one.rib", loud);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err.find("frame 1/"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("run ETA"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace darc::test
