// The frame count behind "frame 3 of 50" and the whole-run estimate.
#include "app/frame_count.h"

#include <gtest/gtest.h>

namespace darc {
namespace {

TEST(FrameCount, FrameBeginRequestsAreCountedAsFramesSelects) {
  const std::string rib = "FrameBegin 1\nWorldBegin\nWorldEnd\nFrameEnd\nFrameBegin 2\nWorldBegin WorldEnd FrameEnd\n"
                          "FrameBegin\t10 WorldBegin WorldEnd FrameEnd\n# MyFrameBegin 3 is no request\n";
  EXPECT_EQ(count_frames_in_text(rib, std::nullopt), 3);
  std::string error;
  EXPECT_EQ(count_frames_in_text(rib, FrameList::parse("2-10", error)), 2);
  EXPECT_EQ(count_frames_in_text(rib, FrameList::parse("3", error)), 0);
}

TEST(FrameCount, WorldBlocksAreFramesWithoutFrameBegin) {
  const std::string rib = "WorldBegin\nWorldEnd\nWorldBegin\nWorldEnd\nWorldBegin\nWorldEnd\n";
  EXPECT_EQ(count_frames_in_text(rib, std::nullopt), 3);
  std::string error;
  EXPECT_EQ(count_frames_in_text(rib, FrameList::parse("2", error)), 1);
}

TEST(FrameCount, StandardInputAndGzipAreUnknown) {
  EXPECT_FALSE(count_frames({"-"}, std::nullopt));
  EXPECT_FALSE(count_frames({"scene.rib.gz"}, std::nullopt));
  EXPECT_FALSE(count_frames({"/nonexistent/scene.rib"}, std::nullopt));
}

}  // namespace
}  // namespace darc
