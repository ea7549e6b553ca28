#include "core/footprint/coverage_mask.h"

#include "core/footprint/coverage.h"

#include <gtest/gtest.h>

#include <cmath>

namespace darc {
namespace {

const FootprintSquare kUnit{1, 0, 0, 1};

TEST(CoverageMask, CentredVerticalBandCoversTheMiddleColumns) {
  // A vertical strand (normal +x) of width 0.25 through the centre covers columns 3 and 4
  // (points at x = -0.0625 and +0.0625), all 8 rows.
  CoverageMask m = band_mask(kUnit, 0, 0, 1, 0, 0.125f);
  EXPECT_EQ(mask_count(m), 16);
  for (int j = 0; j < kMaskSide; ++j) {
    EXPECT_TRUE(m >> (j * kMaskSide + 3) & 1);
    EXPECT_TRUE(m >> (j * kMaskSide + 4) & 1);
    EXPECT_FALSE(m >> (j * kMaskSide + 2) & 1);
  }
}

TEST(CoverageMask, AbuttingStrandsHaveDisjointMasks) {
  CoverageMask left = band_mask(kUnit, -0.25f, 0, 1, 0, 0.25f);
  CoverageMask right = band_mask(kUnit, 0.25f, 0, 1, 0, 0.2499f);
  EXPECT_EQ(left & right, 0u);
  EXPECT_EQ(mask_count(left | right), 64);
}

TEST(CoverageMask, CountApproximatesTheSquareCoverage) {
  for (float angle : {0.0f, 0.3f, 0.7854f, 1.2f})
    for (float d : {0.0f, 0.2f, 0.4f}) {
      float nx = std::cos(angle), ny = std::sin(angle);
      CoverageMask m = band_mask(kUnit, d * nx, d * ny, nx, ny, 0.2f);
      float exact = coverage_square(d, 0.2f, std::abs(nx), std::abs(ny));
      EXPECT_NEAR(mask_count(m) / 64.0f, exact, 0.13f) << angle << " " << d;
    }
}

TEST(CoverageMask, HalfPlaneKeepsTheStrandSide) {
  CoverageMask m = half_plane_mask(kUnit, 0, 0, 1, 0);  // x >= 0
  EXPECT_EQ(mask_count(m), 32);
  EXPECT_TRUE(m >> 7 & 1);
  EXPECT_FALSE(m & 1);
}

}  // namespace
}  // namespace darc
