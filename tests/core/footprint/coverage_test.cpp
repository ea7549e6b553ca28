// The coverage formulas against analytic values: a straight strand of known width under a
// known footprint, centred, offset, half outside and fully outside.
#include "core/footprint/coverage.h"

#include <gtest/gtest.h>

#include <random>

namespace darc {
namespace {

TEST(Coverage, SeedFormulaMatchesItsTwoCaseForm) {
  // The seed's code, verbatim in meaning (uw: half-width, r: footprint radius).
  auto seed = [](float d, float uw, float r) {
    float d0 = d - uw, d1 = d + uw;
    if (d0 >= 0) return (std::min(d1 / r, 1.0f) - std::min(d0 / r, 1.0f)) * 0.5f;
    return (std::min(d1 / r, 1.0f) + std::min(-d0 / r, 1.0f)) * 0.5f;
  };
  for (float d : {0.0f, 0.1f, 0.3f, 0.5f, 0.9f, 1.2f, 3.0f})
    for (float uw : {0.01f, 0.1f, 0.4f, 1.5f}) EXPECT_NEAR(coverage_box(d, uw, 1.0f), seed(d, uw, 1.0f), 1e-6f);
}

TEST(Coverage, BoxCentredOffsetHalfOutsideFullyOutside) {
  const float r = 1.0f;
  EXPECT_NEAR(coverage_box(0.0f, 0.25f, r), 0.25f, 1e-6f);   // width 0.5 of a 2-wide footprint
  EXPECT_NEAR(coverage_box(0.5f, 0.25f, r), 0.25f, 1e-6f);   // offset but fully inside
  EXPECT_NEAR(coverage_box(1.0f, 0.25f, r), 0.125f, 1e-6f);  // half outside
  EXPECT_EQ(coverage_box(1.3f, 0.25f, r), 0.0f);             // fully outside
  EXPECT_NEAR(coverage_box(0.0f, 5.0f, r), 1.0f, 1e-6f);     // wider than the footprint
}

TEST(Coverage, DiscCentredAndHalfPlane) {
  const float r = 1.0f;
  // A band covering the half plane x < 0 (huge width, axis far on the negative side).
  EXPECT_NEAR(coverage_disc(-100.0f, 100.0f, r), 0.5f, 1e-5f);
  // A centred band of half-width h covers (2/pi)(asin h + h sqrt(1-h^2)).
  float h = 0.3f;
  float expected = 2.0f / std::numbers::pi_v<float> * (std::asin(h) + h * std::sqrt(1 - h * h));
  EXPECT_NEAR(coverage_disc(0.0f, h, r), expected, 1e-6f);
  EXPECT_EQ(coverage_disc(1.5f, 0.4f, r), 0.0f);
  EXPECT_NEAR(coverage_disc(0.0f, 2.0f, r), 1.0f, 1e-6f);
}

TEST(Coverage, SquareAxisAlignedIsTheBox) {
  // A band parallel to one side of a unit square: the marginal is a box of width 1.
  for (float d : {0.0f, 0.2f, 0.45f, 0.6f})
    EXPECT_NEAR(coverage_square(d, 0.1f, 1.0f, 0.0f), coverage_box(d, 0.1f, 0.5f), 1e-6f);
}

TEST(Coverage, SquareMatchesMonteCarloForADiagonalBand) {
  // A unit pixel square and a band at 30 degrees: compare with dense point sampling.
  const float angle = 0.5236f, half_width = 0.12f;
  const float nx = std::cos(angle), ny = std::sin(angle);  // band normal
  for (float d : {0.0f, 0.3f, 0.55f, 0.7f}) {
    int inside = 0, total = 0;
    const int n = 400;
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) {
        float x = (i + 0.5f) / n - 0.5f, y = (j + 0.5f) / n - 0.5f;
        float dist = x * nx + y * ny - d;
        inside += std::abs(dist) <= half_width;
        ++total;
      }
    float reference = float(inside) / float(total);
    EXPECT_NEAR(coverage_square(d, half_width, std::abs(nx), std::abs(ny)), reference, 2e-3f) << "d = " << d;
  }
}

TEST(Coverage, AlwaysInUnitIntervalAndFinite) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> u(-3.0f, 3.0f);
  for (int i = 0; i < 10000; ++i) {
    float d = u(rng), h = std::abs(u(rng)), r = std::abs(u(rng)) + 1e-6f;
    for (float c : {coverage_box(d, h, r), coverage_disc(d, h, r), coverage_square(d, h, r, std::abs(u(rng)))}) {
      ASSERT_TRUE(std::isfinite(c));
      ASSERT_GE(c, 0.0f);
      ASSERT_LE(c, 1.0f);
    }
  }
  // Zero width covers nothing; zero-size square degenerates to a hit test.
  EXPECT_EQ(coverage_box(0.0f, 0.0f, 1.0f), 0.0f);
  EXPECT_EQ(coverage_square(0.0f, 0.1f, 0.0f, 0.0f), 1.0f);
  EXPECT_EQ(coverage_square(0.2f, 0.1f, 0.0f, 0.0f), 0.0f);
}

}  // namespace
}  // namespace darc
