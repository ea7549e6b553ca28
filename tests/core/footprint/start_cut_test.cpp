#include "core/footprint/start_cut.h"

#include "core/footprint/polygon_coverage.h"

#include <gtest/gtest.h>

#include <random>

namespace darc {
namespace {

// The sub-rays (u, v) of the footprint square with u cu + v cv < z0, by direct evaluation.
bool starts_before(const StartCut& cut, int i, int j) {
  const float u = (float(i) + 0.5f) / kMaskSide - 0.5f, v = (float(j) + 0.5f) / kMaskSide - 0.5f;
  return u * cut.cu + v * cut.cv < cut.z0;
}

TEST(StartCut, AnUnleaningPatchStartsEverySubRayTogether) {
  // No lean (cu = cv = 0): every sub-ray starts before a strand ahead of the start, none before
  // one behind it.
  EXPECT_EQ(StartCut({0, 0, 0.1f}).share(), 1.0f);
  EXPECT_EQ(StartCut({0, 0, 0.1f}).mask(), kFullMask);
  EXPECT_EQ(StartCut({0, 0, -0.1f}).share(), 0.0f);
  EXPECT_EQ(StartCut({0, 0, -0.1f}).mask(), CoverageMask{0});
}

TEST(StartCut, AStrandAtTheCentreOfAPatchLeaningAlongUIsMetByHalfTheSubRays) {
  // Depth grows with u: the sub-rays of negative u start before the strand at the centre's depth.
  const StartCut cut{1.0f, 0.0f, 0.0f};
  EXPECT_NEAR(cut.share(), 0.5f, 1e-6f);
  const CoverageMask m = cut.mask();
  EXPECT_EQ(mask_count(m), 32);
  for (int j = 0; j < kMaskSide; ++j)
    for (int i = 0; i < kMaskSide; ++i) EXPECT_EQ(bool((m >> (j * kMaskSide + i)) & 1), i < kMaskSide / 2);
}

TEST(StartCut, ShareIsTheHalfPlanesExactAreaAndTheMaskItsPoints) {
  // Random cuts: the share equals the polygon clipper's area of the same half-plane, and the
  // stepped mask equals direct evaluation wherever a point is not on the line (to rounding).
  std::mt19937 rng(17);
  std::uniform_real_distribution<float> slope(-2.0f, 2.0f), offset(-1.2f, 1.2f);
  for (int k = 0; k < 500; ++k) {
    const StartCut cut{slope(rng), slope(rng), offset(rng)};
    const FootprintHalfPlane plane{cut.z0, -cut.cu, -cut.cv};
    EXPECT_NEAR(cut.share(), footprint_area_within(std::span(&plane, 1)), 2e-5) << k;
    const CoverageMask m = cut.mask();
    for (int j = 0; j < kMaskSide; ++j)
      for (int i = 0; i < kMaskSide; ++i) {
        const float u = (float(i) + 0.5f) / kMaskSide - 0.5f, v = (float(j) + 0.5f) / kMaskSide - 0.5f;
        if (std::abs(u * cut.cu + v * cut.cv - cut.z0) < 1e-5f) continue;
        EXPECT_EQ(bool((m >> (j * kMaskSide + i)) & 1), starts_before(cut, i, j)) << k << " " << i << " " << j;
      }
  }
}

}  // namespace
}  // namespace darc
