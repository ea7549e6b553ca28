#include "core/footprint/coverage_mask.h"

#include "core/footprint/coverage.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <utility>
#include <vector>

#include <cmath>

namespace darc {
namespace {

const FootprintSquare kUnit{1, 0, 0, 1};
constexpr int kMaskPoints = kMaskSide * kMaskSide;
// Mask point b's footprint coordinates, as nearest_points_mask computes them.
float mask_point_u_of(int b) { return (float(b % kMaskSide) + 0.5f) * (1.0f / kMaskSide) - 0.5f; }
float mask_point_v_of(int b) { return (float(b / kMaskSide) + 0.5f) * (1.0f / kMaskSide) - 0.5f; }

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

TEST(CoverageMask, AMaskHoldsItsCoverage) {
  EXPECT_EQ(mask_points_for(5.2f / 64.0f), 6);
  EXPECT_EQ(mask_points_for(5.0f / 64.0f), 5);  // a whole count, give or take rounding
  EXPECT_EQ(mask_points_for(5.0001f / 64.0f), 5);
  EXPECT_EQ(mask_points_for(0.0f), 1);
  EXPECT_EQ(mask_points_for(1.0f), 64);
  EXPECT_EQ(mask_points_for(2.0f), 64);
}

TEST(CoverageMask, DilateAddsTheEightNeighboursWithoutWrapping) {
  EXPECT_EQ(dilate_mask(CoverageMask{1} << (3 * kMaskSide + 3)), CoverageMask{0x1c1c1c} << (2 * kMaskSide));
  // A point on the last column of a row grows to its row's columns 6 and 7, never to the next
  // row's column 0; the corner point keeps to its corner.
  const CoverageMask edge = dilate_mask(CoverageMask{1} << (2 * kMaskSide + 7));
  EXPECT_EQ(mask_count(edge), 6);
  EXPECT_FALSE(edge >> (3 * kMaskSide) & 1);
  EXPECT_EQ(dilate_mask(1), CoverageMask{0x303});
  EXPECT_EQ(dilate_mask(kFullMask), kFullMask);
}

float spread_total(const CoverageSpread& s) {
  float sum = 0;
  for (int b = 0; b < 64; ++b) sum += s.at(b);
  return sum / 64.0f;
}

TEST(CoverageMask, SpreadKeepsTheCoverageWithinTheMaskWhenItFits) {
  const CoverageMask m = 0xf0;  // four points
  const CoverageSpread s = spread_coverage(m, 3.0f / 64.0f);
  EXPECT_EQ(s.full, m);
  EXPECT_EQ(s.ring, 0u);
  EXPECT_FLOAT_EQ(s.full_opacity, 0.75f);
  EXPECT_NEAR(spread_total(s), 3.0f / 64.0f, 1e-7f);
}

TEST(CoverageMask, SpreadPutsTheExcessOnTheNeighboursOnly) {
  // One point in the middle holding 1.5 points' worth: the half goes to its eight neighbours,
  // the rest of the footprint stays clear.
  const CoverageMask centre = CoverageMask{1} << (4 * kMaskSide + 4);
  const CoverageSpread s = spread_coverage(centre, 1.5f / 64.0f);
  EXPECT_FLOAT_EQ(s.full_opacity, 1.0f);
  EXPECT_EQ(s.ring, dilate_mask(centre) & ~centre);
  EXPECT_FLOAT_EQ(s.ring_opacity, 0.5f / 8.0f);
  EXPECT_NEAR(spread_total(s), 1.5f / 64.0f, 1e-7f);
  EXPECT_EQ(s.at(0), 0.0f);
  // More than the first ring holds: it fills, and the next ring takes the rest.
  const CoverageSpread wide = spread_coverage(centre, 12.0f / 64.0f);
  EXPECT_EQ(wide.full, dilate_mask(centre));
  EXPECT_EQ(wide.ring, dilate_mask(dilate_mask(centre)) & ~dilate_mask(centre));
  EXPECT_NEAR(spread_total(wide), 12.0f / 64.0f, 1e-6f);
  // An empty mask says nowhere in particular: the coverage is spread over the whole footprint.
  EXPECT_NEAR(spread_coverage(0, 0.25f).at(17), 0.25f, 1e-7f);
  EXPECT_NEAR(spread_total(spread_coverage(kFullMask, 1.0f)), 1.0f, 1e-7f);
}

TEST(CoverageMask, MaskPointTimesAreStratifiedInEveryRowAndColumn) {
  std::set<int> all;
  for (int line = 0; line < kMaskSide; ++line) {
    std::set<int> row_eighths, column_eighths;
    for (int k = 0; k < kMaskSide; ++k) {
      row_eighths.insert(int(mask_point_time(line * kMaskSide + k) * kMaskSide));
      column_eighths.insert(int(mask_point_time(k * kMaskSide + line) * kMaskSide));
    }
    EXPECT_EQ(row_eighths.size(), size_t(kMaskSide)) << "row " << line;
    EXPECT_EQ(column_eighths.size(), size_t(kMaskSide)) << "column " << line;
  }
  for (int b = 0; b < kMaskSide * kMaskSide; ++b) all.insert(int(mask_point_time(b) * 64));
  EXPECT_EQ(all.size(), 64u) << "one time per point";
}

TEST(CoverageMask, ASweptLineTakesThePointsItPassesAtTheirTimes) {
  // A vertical line moving across a unit square from x = -1 to x = +1 during the shutter: at the
  // time of each point it takes, it is within half a column of it.
  const FootprintSquare sq{1, 0, 0, 1};
  const SweptLine sweep{0, 1, -1, 1, true};
  const CoverageMask m = nearest_points_mask(sq, 0, 0, 1, 0, false, 8, kFullMask, &sweep);
  EXPECT_EQ(mask_count(m), 8);
  for (int b = 0; b < 64; ++b)
    if ((m >> b) & 1) {
      const float x = (float(b % kMaskSide) + 0.5f) / kMaskSide - 0.5f;
      EXPECT_NEAR(x, -1 + 2 * mask_point_time(b), 1.0 / kMaskSide) << b;
    }
  // Two lines a third of a square apart take different points.
  const SweptLine later{0, 1, -1.33f, 0.67f, true};
  EXPECT_EQ(m & nearest_points_mask(sq, 0, 0, 1, 0, false, 8, kFullMask, &later), 0u);
}

// The nearest points are the `count` smallest (distance, index) pairs among the allowed points,
// whichever way they are selected (a short sorted list for few points, nth_element for many):
// checked against a full sort, for lines, end-on points and masks that forbid points, with ties
// (a line along the grid puts whole columns at one distance).
TEST(CoverageMask, NearestPointsAreTheSmallestDistancesTiesToTheLowerIndex) {
  const FootprintSquare tilted{0.9f, 0.3f, -0.2f, 1.1f};
  uint64_t state = 12345;
  auto next = [&] {
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    return float(state >> 40) / float(1 << 24);
  };
  for (int trial = 0; trial < 200; ++trial) {
    const FootprintSquare& sq = trial % 3 == 0 ? kUnit : tilted;
    const bool point = trial % 5 == 0;
    const float angle = trial % 4 == 0 ? 0.0f : 6.2831853f * next();
    const float nx = std::cos(angle), ny = std::sin(angle);
    const float cx = next() - 0.5f, cy = next() - 0.5f;
    const CoverageMask allowed = trial % 2 == 0 ? kFullMask : (CoverageMask(state) | 1u);
    const int count = 1 + trial % kMaskPoints;
    std::vector<std::pair<float, int>> order;
    for (int b = 0; b < kMaskPoints; ++b) {
      if (!((allowed >> b) & 1)) continue;
      const float u = mask_point_u_of(b), v = mask_point_v_of(b);
      const float px = u * sq.ax_x + v * sq.ay_x - cx, py = u * sq.ax_y + v * sq.ay_y - cy;
      order.push_back({point ? px * px + py * py : std::abs(px * nx + py * ny), b});
    }
    std::sort(order.begin(), order.end());
    CoverageMask expected = 0;
    for (int k = 0; k < count && k < int(order.size()); ++k) expected |= CoverageMask{1} << order[size_t(k)].second;
    EXPECT_EQ(nearest_points_mask(sq, cx, cy, nx, ny, point, count, allowed), expected)
        << "trial " << trial << ", count " << count;
  }
}

}  // namespace
}  // namespace darc
