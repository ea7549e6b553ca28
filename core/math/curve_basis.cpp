#include "core/math/curve_basis.h"

#include <cmath>
#include <utility>

namespace darc {

namespace {

// Matrices from the RI spec (values as in aqsis risyms.cpp, checked by the unit tests).
constexpr std::array<double, 16> kBezierMatrix = {-1, 3, -3, 1, 3, -6, 3, 0, -3, 3, 0, 0, 1, 0, 0, 0};
constexpr double kSixth = 1.0 / 6.0;
constexpr std::array<double, 16> kBSplineMatrix = {-kSixth,    3 * kSixth, -3 * kSixth, kSixth, 3 * kSixth, -6 * kSixth,
                                                   3 * kSixth, 0,          -3 * kSixth, 0,      3 * kSixth, 0,
                                                   kSixth,     4 * kSixth, kSixth,      0};
constexpr std::array<double, 16> kCatmullRomMatrix = {-0.5, 1.5, -1.5, 0.5, 1, -2.5, 2, -0.5,
                                                      -0.5, 0,   0.5,  0,   0, 1,    0, 0};
constexpr std::array<double, 16> kHermiteMatrix = {2, 1, -2, 1, -3, -2, 3, -1, 0, 1, 0, 0, 1, 0, 0, 0};
constexpr std::array<double, 16> kPowerMatrix = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};

// The inverse of the Bézier basis matrix, exact (rows give Bézier control values from the
// power coefficients: b0 = d, b1 = d + c/3, b2 = d + 2c/3 + b/3, b3 = a + b + c + d).
constexpr double kThird = 1.0 / 3.0;
constexpr std::array<double, 16> kBezierInverse = {0, 0,      0,          1,  //
                                                   0, 0,      kThird,     1,  //
                                                   0, kThird, 2 * kThird, 1,  //
                                                   1, 1,      1,          1};

std::array<double, 16> multiply(const std::array<double, 16>& a, const std::array<double, 16>& b) {
  std::array<double, 16> r{};
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      for (int k = 0; k < 4; ++k) r[i * 4 + j] += a[i * 4 + k] * b[k * 4 + j];
  return r;
}

}  // namespace

CurveBasis bezier_basis() { return {kBezierMatrix, kBezierStep}; }

CurveBasis basis_from_matrix(const std::array<double, 16>& m, int step) { return {m, step}; }

std::optional<CurveBasis> standard_basis(std::string_view name) {
  if (name == "bezier") return CurveBasis{kBezierMatrix, kBezierStep};
  if (name == "b-spline") return CurveBasis{kBSplineMatrix, kBSplineStep};
  if (name == "catmull-rom") return CurveBasis{kCatmullRomMatrix, kCatmullRomStep};
  if (name == "hermite") return CurveBasis{kHermiteMatrix, kHermiteStep};
  if (name == "power") return CurveBasis{kPowerMatrix, kPowerStep};
  return std::nullopt;
}

double evaluate_basis(const CurveBasis& basis, const std::array<double, 4>& g, double t) {
  const double powers[4] = {t * t * t, t * t, t, 1.0};
  double result = 0;
  for (int col = 0; col < 4; ++col) {
    double weight = 0;
    for (int row = 0; row < 4; ++row) weight += powers[row] * basis.m[row * 4 + col];
    result += weight * g[col];
  }
  return result;
}

BezierConversion bezier_conversion(const CurveBasis& basis) { return {multiply(kBezierInverse, basis.m)}; }

}  // namespace darc
