#include "core/math/polynomial_roots.h"

#include <gtest/gtest.h>

#include <cmath>

namespace darc {
namespace {

TEST(PolynomialRoots, FourSimpleRootsInOrder) {
  // (x - 1)(x - 2)(x - 3)(x - 4) = x^4 - 10 x^3 + 35 x^2 - 50 x + 24
  const double c[5] = {24, -50, 35, -10, 1};
  double r[4];
  ASSERT_EQ(polynomial_roots(c, 4, -10, 10, 0, r), 4);
  for (int i = 0; i < 4; ++i) EXPECT_NEAR(r[i], i + 1, 1e-14);
  EXPECT_EQ(polynomial_roots(c, 4, 1.5, 3.5, 0, r), 2);  // only those in the interval
  EXPECT_NEAR(r[0], 2, 1e-14);
  EXPECT_NEAR(r[1], 3, 1e-14);
}

TEST(PolynomialRoots, TouchingRootCountsWithinTheTolerance) {
  // (x - 1)^2 (x + 2)(x - 3) = x^4 - 3 x^3 - 3 x^2 + 11 x - 6: a double root at 1.
  const double c[5] = {-6, 11, -3, -3, 1};
  double r[4];
  ASSERT_EQ(polynomial_roots(c, 4, -5, 5, 1e-12, r), 3);
  EXPECT_NEAR(r[0], -2, 1e-13);
  EXPECT_NEAR(r[1], 1, 1e-7);
  EXPECT_NEAR(r[2], 3, 1e-13);
  // The double root is a local maximum (the other factors are -6 there). Lowered by 1e-6 it is
  // gone, and the tolerance does not bring it back; raised by 1e-10 it is two close simple roots,
  // found by their sign changes.
  const double lowered[5] = {-6 - 1e-6, 11, -3, -3, 1};
  EXPECT_EQ(polynomial_roots(lowered, 4, 0, 2, 1e-12, r), 0);
  const double raised[5] = {-6 + 1e-10, 11, -3, -3, 1};
  ASSERT_EQ(polynomial_roots(raised, 4, 0, 2, 1e-12, r), 2);
  EXPECT_NEAR(r[0], 1 - std::sqrt(1e-10 / 6), 1e-8);
  EXPECT_NEAR(r[1], 1 + std::sqrt(1e-10 / 6), 1e-8);
}

TEST(PolynomialRoots, LowerDegreesAndDegenerateInput) {
  double r[4];
  const double quadratic_as_quartic[5] = {-1, 0, 1, 0, 0};  // x^2 - 1 with zero leading terms
  ASSERT_EQ(polynomial_roots(quadratic_as_quartic, 4, -2, 2, 0, r), 2);
  EXPECT_DOUBLE_EQ(r[0], -1);
  EXPECT_DOUBLE_EQ(r[1], 1);
  const double zero[5] = {0, 0, 0, 0, 0};
  EXPECT_EQ(polynomial_roots(zero, 4, -1, 1, 0, r), 0);
  const double constant[1] = {3};
  EXPECT_EQ(polynomial_roots(constant, 0, -1, 1, 0, r), 0);
  const double no_real[3] = {1, 0, 1};  // x^2 + 1
  EXPECT_EQ(polynomial_roots(no_real, 2, -5, 5, 0, r), 0);
  EXPECT_EQ(polynomial_roots(quadratic_as_quartic, 4, 2, -2, 0, r), 0);  // empty interval
}

}  // namespace
}  // namespace darc
