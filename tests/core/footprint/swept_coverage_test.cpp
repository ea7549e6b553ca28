// Time-swept coverage in closed form against the other order of integration: the static
// coverage averaged over many times along the motion (midpoint rule, 20000 steps).
#include "core/footprint/swept_coverage.h"

#include <gtest/gtest.h>

#include <random>

namespace darc {
namespace {

template <class Static>
double averaged_over_time(double d0, double d1, Static&& at) {
  constexpr int kSteps = 20000;
  double sum = 0;
  for (int i = 0; i < kSteps; ++i) sum += at(d0 + (d1 - d0) * (i + 0.5) / kSteps);
  return sum / kSteps;
}

TEST(SweptCoverage, EachFootprintMatchesTheStaticCoverageAveragedOverTime) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> d(-1.5, 1.5), motion(-4.0, 4.0), half(0.01, 0.8), side(0.2, 1.0);
  double worst_box = 0, worst_disc = 0, worst_square = 0;
  for (int i = 0; i < 200; ++i) {
    const double d0 = d(rng), d1 = d0 + motion(rng), hw = half(rng), a = side(rng), b = side(rng);
    worst_box = std::max(worst_box, std::abs(swept_coverage_box(d0, d1, hw, 0.5) -
                                             averaged_over_time(d0, d1, [&](double x) {
                                               return coverage_box(float(x), float(hw), 0.5f);
                                             })));
    worst_disc = std::max(worst_disc, std::abs(swept_coverage_disc(d0, d1, hw, 0.6) -
                                               averaged_over_time(d0, d1, [&](double x) {
                                                 return coverage_disc(float(x), float(hw), 0.6f);
                                               })));
    worst_square = std::max(worst_square, std::abs(swept_coverage_square(d0, d1, hw, a, b) -
                                                   averaged_over_time(d0, d1, [&](double x) {
                                                     return coverage_square(float(x), float(hw), float(a), float(b));
                                                   })));
  }
  // The reference is a float average of float coverages: 1e-5 is its rounding, not the formula's.
  EXPECT_LT(worst_box, 2e-5);
  EXPECT_LT(worst_disc, 2e-5);
  EXPECT_LT(worst_square, 2e-5);
}

TEST(SweptCoverage, AThinBandSweptFarAcrossAPixelLeavesItsWidthOverTheSweep) {
  // w = 0.2 px swept L = 5 px over a unit pixel square, the pixel well inside the sweep: w / L.
  EXPECT_NEAR(swept_coverage_square(-2.5, 2.5, 0.1, 1.0, 0.0), 0.2 / 5.0, 1e-7);
  EXPECT_NEAR(swept_coverage_square(-2.5, 2.5, 0.1, 0.7071, 0.7071), 0.2 / 5.0, 1e-7);
  // The same whichever way it moves.
  EXPECT_FLOAT_EQ(swept_coverage_box(-1.0, 2.0, 0.1, 0.5), swept_coverage_box(2.0, -1.0, 0.1, 0.5));
}

TEST(SweptCoverage, NoMotionIsTheStaticCoverage) {
  EXPECT_FLOAT_EQ(swept_coverage_box(0.3, 0.3, 0.2, 0.5), coverage_box(0.3f, 0.2f, 0.5f));
  EXPECT_FLOAT_EQ(swept_coverage_disc(0.3, 0.3, 0.2, 0.5), coverage_disc(0.3f, 0.2f, 0.5f));
  EXPECT_FLOAT_EQ(swept_coverage_square(0.3, 0.3, 0.2, 1.0, 0.5), coverage_square(0.3f, 0.2f, 1.0f, 0.5f));
  // A motion of 1e-4 footprints is already the swept formula, and within rounding of static.
  EXPECT_NEAR(swept_coverage_square(0.3, 0.3001, 0.2, 1.0, 0.5), coverage_square(0.30005f, 0.2f, 1.0f, 0.5f), 1e-5);
}

}  // namespace
}  // namespace darc
