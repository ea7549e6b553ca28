// The frame memory limit: the estimate stays above what the built structures hold, a frame
// whose geometry would go over the limit fails at the request that crosses it (and renders
// nothing), and the next frame starts from zero.
#include "core/scene/frame_memory.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <random>
#include <string>

#include "support/scenes_from_rib.h"

namespace darc::test {
namespace {

// One Curves request (one line) of `strands` random cubic Bézier strands of 10 segments each.
std::string curves_line(int strands, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  std::string rib = "Curves \"cubic\" [";
  for (int i = 0; i < strands; ++i) rib += " 31";
  rib += "] \"nonperiodic\" \"P\" [";
  for (int i = 0; i < strands; ++i) {
    float x = u(rng), y = u(rng), z = u(rng);
    for (int v = 0; v < 31; ++v) {
      char point[64];
      std::snprintf(point, sizeof point, " %.4f %.4f %.4f", x + 0.01f * float(v) * u(rng), y + 0.01f * float(v), z);
      rib += point;
    }
  }
  rib += "] \"constantwidth\" [0.01]\n";
  return rib;
}

std::string hair_world(int strands, unsigned seed) { return "WorldBegin\n" + curves_line(strands, seed) + "WorldEnd\n"; }

TEST(FrameMemory, EstimateCoversTheCurvesAndEitherAcceleratorAfterTheBuild) {
  for (AcceleratorKind kind : {AcceleratorKind::Bvh, AcceleratorKind::Grid}) {
    Built b = build(hair_world(2000, 3));
    ASSERT_EQ(b.scenes.size(), 1u);
    Scene& scene = b.scenes[0];
    const size_t segments = scene.curves.size();
    ASSERT_EQ(segments, 20000u);
    scene.build_acceleration(kind);
    const uint64_t held = scene.curves.memory_bytes() + scene.accel.memory_bytes();
    EXPECT_GT(frame_memory_estimate(segments, 0, 0), held) << "accelerator " << int(kind);
  }
}

TEST(FrameMemory, FrameOverTheLimitFailsAtTheRequestThatCrossesItAndRendersNothing) {
  FrameOverrides limits;
  // Room for the first request (1000 strands, 10000 segments) but not for the second.
  limits.memory_limit_bytes = frame_memory_estimate(15000, 0, 0) + 640 * 480 * kFrameBytesPerPixel;  // + the image
  limits.memory_limit_source = "the limit is a test's";
  const std::string rib = "FrameBegin 1\nWorldBegin\n" + curves_line(1000, 1) + "Sphere 1 -1 1 360\n" +
                          curves_line(1000, 2) + "Sphere 1 -1 1 360\nWorldEnd\nFrameEnd\n" + "FrameBegin 2\n" +
                          hair_world(100, 5) + "FrameEnd\n";
  Built b = build(rib, {}, limits);
  ASSERT_EQ(b.failed.size(), 1u);
  EXPECT_EQ(b.failed[0], 1);
  ASSERT_EQ(b.scenes.size(), 1u) << "the next frame starts with nothing reserved";
  EXPECT_EQ(b.scenes[0].output.frame_number, 2);
  EXPECT_EQ(b.scenes[0].curves.size(), 1000u);
  EXPECT_TRUE(b.scenes[0].surfaces.spheres.empty());
  size_t errors = 0;
  for (const Diagnostic& d : b.diagnostics) {
    if (d.severity != Severity::Error) continue;
    ++errors;
    EXPECT_EQ(d.loc.line, 5) << "the second Curves request (line 5) crosses the limit: " << d.str();
    EXPECT_NE(d.message.find("more than the"), std::string::npos) << d.str();
    EXPECT_NE(d.message.find("the limit is a test's"), std::string::npos) << d.str();
    EXPECT_NE(d.message.find("the frame is not rendered"), std::string::npos) << d.str();
  }
  EXPECT_EQ(errors, 1u) << "one error: the frame's later geometry is skipped without more messages";
}

// The image counts with the geometry (kFrameBytesPerPixel): a frame whose image alone passes the
// limit fails at WorldEnd when it has no geometry, and at its first geometry request otherwise.
TEST(FrameMemory, AnImageOverTheLimitFailsTheFrame) {
  FrameOverrides limits;
  limits.memory_limit_bytes = 1000 * 1000 * kFrameBytesPerPixel;  // a 1000x1000 image, nothing else
  limits.memory_limit_source = "a test's";
  Built b = build("Format 2000 1000 1\nFrameBegin 1\nWorldBegin\nWorldEnd\nFrameEnd\n"
                  "FrameBegin 2\nWorldBegin\nSphere 1 -1 1 360\nWorldEnd\nFrameEnd\n"
                  "Format 1000 1000 1\nFrameBegin 3\nWorldBegin\nWorldEnd\nFrameEnd\n",
                  {}, limits);
  EXPECT_EQ(b.failed, (std::vector<int>{1, 2}));
  ASSERT_EQ(b.scenes.size(), 1u) << "the image that fits renders";
  EXPECT_EQ(b.scenes[0].output.frame_number, 3);
  std::vector<Diagnostic> errors;
  for (const Diagnostic& d : b.diagnostics)
    if (d.severity == Severity::Error) errors.push_back(d);
  ASSERT_EQ(errors.size(), 2u);
  EXPECT_EQ(errors[0].loc.line, 4);
  EXPECT_EQ(errors[0].request, "WorldEnd");
  EXPECT_EQ(errors[0].message, "the frame would need about 244 MB in all (its geometry and 244 MB for its image), "
                               "more than the 122 MB a frame may use (a test's); the frame is not rendered");
  EXPECT_EQ(errors[1].loc.line, 8);
  EXPECT_EQ(errors[1].request, "Sphere");
}

TEST(FrameMemory, NoLimitBuildsEverything) {
  Built b = build(hair_world(1000, 1));
  ASSERT_EQ(b.scenes.size(), 1u);
  EXPECT_TRUE(b.failed.empty());
  EXPECT_EQ(b.scenes[0].curves.size(), 10000u);
}

TEST(FrameMemory, BytesAreWrittenInTheUnitsSlurmUses) {
  EXPECT_EQ(format_bytes(512), "0 kB");
  EXPECT_EQ(format_bytes(300 * 1024), "300 kB");
  EXPECT_EQ(format_bytes(uint64_t(340) << 20), "340 MB");
  EXPECT_EQ(format_bytes(uint64_t(3) << 29), "1.5 GB");
}

}  // namespace
}  // namespace darc::test
