// Cubic curve bases in the RenderMan convention, and the cubic Bézier form that every curve
// segment is converted to at load time (so the intersector sees one representation only).
#pragma once

#include <array>
#include <optional>
#include <string_view>

namespace darc {

// A segment with control values G0..G3 is C(t) = [t^3 t^2 t 1] * M * [G0 G1 G2 G3]^T, t in [0,1].
// m is row-major (RIB order). step is how many control values one segment advances to the next
// (RiBasis vstep).
struct CurveBasis {
  std::array<double, 16> m{};
  int step = 3;
};

// The RI standard steps (ri.h: RI_BEZIERSTEP ...).
inline constexpr int kBezierStep = 3;
inline constexpr int kBSplineStep = 1;
inline constexpr int kCatmullRomStep = 1;
inline constexpr int kHermiteStep = 2;
inline constexpr int kPowerStep = 4;

// "bezier", "b-spline", "catmull-rom", "hermite", "power"; nullopt for any other name.
// Hermite control values are (P0, T0, P1, T1); power control values are the coefficients of
// t^3, t^2, t, 1.
std::optional<CurveBasis> standard_basis(std::string_view name);
CurveBasis bezier_basis();
// A basis given as 16 numbers in RIB (row-major) order.
CurveBasis basis_from_matrix(const std::array<double, 16>& m, int step);

// Evaluates one component of a segment in its own basis: [t^3 t^2 t 1] * M * g.
double evaluate_basis(const CurveBasis& basis, const std::array<double, 4>& g, double t);

// The 4x4 matrix C = M_bezier^-1 * M_basis (row-major): the Bézier control values of a segment
// are C * G. Compute it once per basis, then apply it to every segment and every primvar.
struct BezierConversion {
  std::array<double, 16> c{};

  // Converts four control values (scalars or vectors of double) of one segment.
  template <typename T>
  std::array<T, 4> apply(const std::array<T, 4>& g) const {
    std::array<T, 4> out;
    for (int i = 0; i < 4; ++i)
      out[i] = g[0] * c[i * 4 + 0] + g[1] * c[i * 4 + 1] + g[2] * c[i * 4 + 2] + g[3] * c[i * 4 + 3];
    return out;
  }
};
BezierConversion bezier_conversion(const CurveBasis& basis);

// ---- Cubic Bézier helpers, generic over float and Vec3f (anything with +, -, * float) ----

// Point at u by de Casteljau (stable for u in [0,1]).
template <typename T>
T bezier_evaluate(const T cp[4], float u) {
  T a = cp[0] + (cp[1] - cp[0]) * u, b = cp[1] + (cp[2] - cp[1]) * u, c = cp[2] + (cp[3] - cp[2]) * u;
  T d = a + (b - a) * u, e = b + (c - b) * u;
  return d + (e - d) * u;
}

// dC/du at u.
template <typename T>
T bezier_derivative(const T cp[4], float u) {
  T a = cp[1] - cp[0], b = cp[2] - cp[1], c = cp[3] - cp[2];
  T d = a + (b - a) * u, e = b + (c - b) * u;
  return (d + (e - d) * u) * 3.0f;
}

// Splits at u = 1/2: the halves are out[0..3] and out[3..6].
template <typename T>
void bezier_split_half(const T cp[4], T out[7]) {
  T a = (cp[0] + cp[1]) * 0.5f, b = (cp[1] + cp[2]) * 0.5f, c = (cp[2] + cp[3]) * 0.5f;
  T d = (a + b) * 0.5f, e = (b + c) * 0.5f;
  out[0] = cp[0];
  out[1] = a;
  out[2] = d;
  out[3] = (d + e) * 0.5f;
  out[4] = e;
  out[5] = c;
  out[6] = cp[3];
}

}  // namespace darc
