// The five RenderMan bases against their defining properties, and their exact conversion to
// cubic Bézier form.
#include "core/math/curve_basis.h"

#include <gtest/gtest.h>

#include <array>

namespace darc {
namespace {

constexpr double kExact = 1e-12;
constexpr double kDerivativeStep = 1e-5;       // central difference step
constexpr double kDerivativeTolerance = 1e-7;  // O(step^2) truncation plus rounding

CurveBasis basis(const char* name) {
  auto b = standard_basis(name);
  EXPECT_TRUE(b.has_value()) << name;
  return b.value_or(bezier_basis());
}

double derivative(const CurveBasis& b, const std::array<double, 4>& g, double t) {
  return (evaluate_basis(b, g, t + kDerivativeStep) - evaluate_basis(b, g, t - kDerivativeStep)) /
         (2 * kDerivativeStep);
}

const std::array<double, 4> kG = {0.7, -1.3, 2.9, 4.1};

TEST(CurveBasis, StepsFollowRiH) {
  EXPECT_EQ(basis("bezier").step, 3);
  EXPECT_EQ(basis("b-spline").step, 1);
  EXPECT_EQ(basis("catmull-rom").step, 1);
  EXPECT_EQ(basis("hermite").step, 2);
  EXPECT_EQ(basis("power").step, 4);
  EXPECT_FALSE(standard_basis("bspline").has_value());
  EXPECT_FALSE(standard_basis("").has_value());
}

TEST(CurveBasis, BezierInterpolatesEndsWithHullTangents) {
  CurveBasis b = basis("bezier");
  EXPECT_NEAR(evaluate_basis(b, kG, 0), kG[0], kExact);
  EXPECT_NEAR(evaluate_basis(b, kG, 1), kG[3], kExact);
  EXPECT_NEAR(derivative(b, kG, 0), 3 * (kG[1] - kG[0]), kDerivativeTolerance);
  EXPECT_NEAR(derivative(b, kG, 1), 3 * (kG[3] - kG[2]), kDerivativeTolerance);
}

TEST(CurveBasis, CatmullRomPassesThroughInnerPoints) {
  CurveBasis b = basis("catmull-rom");
  EXPECT_NEAR(evaluate_basis(b, kG, 0), kG[1], kExact);
  EXPECT_NEAR(evaluate_basis(b, kG, 1), kG[2], kExact);
  EXPECT_NEAR(derivative(b, kG, 0), (kG[2] - kG[0]) / 2, kDerivativeTolerance);
  EXPECT_NEAR(derivative(b, kG, 1), (kG[3] - kG[1]) / 2, kDerivativeTolerance);
}

TEST(CurveBasis, BSplineKnownValues) {
  CurveBasis b = basis("b-spline");
  EXPECT_NEAR(evaluate_basis(b, kG, 0), (kG[0] + 4 * kG[1] + kG[2]) / 6, kExact);
  EXPECT_NEAR(evaluate_basis(b, kG, 1), (kG[1] + 4 * kG[2] + kG[3]) / 6, kExact);
  EXPECT_NEAR(evaluate_basis(b, kG, 0.5), (kG[0] + 23 * kG[1] + 23 * kG[2] + kG[3]) / 48, kExact);
  EXPECT_NEAR(derivative(b, kG, 0), (kG[2] - kG[0]) / 2, kDerivativeTolerance);
  // Partition of unity: a constant stays constant.
  EXPECT_NEAR(evaluate_basis(b, {5, 5, 5, 5}, 0.37), 5.0, kExact);
}

TEST(CurveBasis, HermiteEndpointsAndTangents) {
  CurveBasis b = basis("hermite");
  // Geometry order (P0, T0, P1, T1).
  const std::array<double, 4> g = {1.5, -2.0, 4.0, 0.5};
  EXPECT_NEAR(evaluate_basis(b, g, 0), 1.5, kExact);
  EXPECT_NEAR(evaluate_basis(b, g, 1), 4.0, kExact);
  EXPECT_NEAR(derivative(b, g, 0), -2.0, kDerivativeTolerance);
  EXPECT_NEAR(derivative(b, g, 1), 0.5, kDerivativeTolerance);
}

TEST(CurveBasis, PowerIsPolynomialCoefficients) {
  CurveBasis b = basis("power");
  double t = 0.3;
  EXPECT_NEAR(evaluate_basis(b, kG, t), kG[0] * t * t * t + kG[1] * t * t + kG[2] * t + kG[3], kExact);
}

// aqsis Bug1102597: power coefficients [-2 0 0, 3 -3 0, 0 3 0, 0 0 0] are exactly the Bézier
// curve (0,0,0)(0,1,0)(1,1,0)(1,0,0).
TEST(CurveBasis, PowerExampleConvertsToKnownBezier) {
  BezierConversion c = bezier_conversion(basis("power"));
  std::array<double, 4> x = c.apply(std::array<double, 4>{-2, 3, 0, 0});
  std::array<double, 4> y = c.apply(std::array<double, 4>{0, -3, 3, 0});
  const double expected_x[4] = {0, 0, 1, 1}, expected_y[4] = {0, 1, 1, 0};
  for (int i = 0; i < 4; ++i) {
    EXPECT_NEAR(x[i], expected_x[i], kExact) << i;
    EXPECT_NEAR(y[i], expected_y[i], kExact) << i;
  }
}

// The Bézier form must be the same curve as the original basis, for every standard basis and a
// user matrix.
TEST(CurveBasis, ConversionToBezierIsExact) {
  std::array<double, 16> custom = {0.5, -1, 2, 0.25, 1, 0, -3, 1, 2, 2, 0, -1, 0.1, 0.2, 0.3, 0.4};
  std::vector<CurveBasis> bases = {basis("bezier"),  basis("b-spline"), basis("catmull-rom"),
                                   basis("hermite"), basis("power"),    basis_from_matrix(custom, 1)};
  const std::array<double, 4> g = {0.25, -1.5, 3.0, 2.0};
  for (size_t i = 0; i < bases.size(); ++i) {
    std::array<double, 4> bez = bezier_conversion(bases[i]).apply(g);
    for (double t : {0.0, 0.1, 0.25, 0.5, 0.8, 1.0}) {
      double expected = evaluate_basis(bases[i], g, t);
      double via_bezier = evaluate_basis(bezier_basis(), bez, t);
      EXPECT_NEAR(via_bezier, expected, 1e-6) << "basis " << i << " t " << t;
      // The float evaluator agrees too (to float precision).
      float bez_f[4] = {float(bez[0]), float(bez[1]), float(bez[2]), float(bez[3])};
      EXPECT_NEAR(bezier_evaluate(bez_f, float(t)), expected, 1e-5) << "basis " << i << " t " << t;
    }
  }
}

TEST(CurveBasis, BezierHelpersSplitAndDifferentiate) {
  float cp[4] = {1, 3, -2, 5};
  float halves[7];
  bezier_split_half(cp, halves);
  for (float s : {0.0f, 0.3f, 1.0f}) {
    EXPECT_NEAR(bezier_evaluate(halves, s), bezier_evaluate(cp, 0.5f * s), 1e-5);
    EXPECT_NEAR(bezier_evaluate(halves + 3, s), bezier_evaluate(cp, 0.5f + 0.5f * s), 1e-5);
  }
  EXPECT_FLOAT_EQ(bezier_derivative(cp, 0.0f), 3 * (cp[1] - cp[0]));
  EXPECT_FLOAT_EQ(bezier_derivative(cp, 1.0f), 3 * (cp[3] - cp[2]));
}

}  // namespace
}  // namespace darc
