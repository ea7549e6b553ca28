#include "core/math/polynomial_roots.h"

#include <algorithm>
#include <cmath>

namespace darc {

namespace {

// Newton iterations per bracketed root: each step at least halves the bracket (a bisection
// replaces a Newton step that leaves it), so 100 steps reach double precision from any start.
constexpr int kMaxRootIterations = 100;
// Roots closer than this (relative to the interval) are one root: a sign change found at a
// breakpoint and the touching root at the same critical point must not count twice.
constexpr double kRootMergeRelative = 1e-12;

// The one root of c on [a, b], where c(a) and c(b) have opposite signs and c is monotone.
double bracketed_root(const double* c, int degree, double a, double b, double fa) {
  double x = 0.5 * (a + b);
  for (int i = 0; i < kMaxRootIterations; ++i) {
    double f = c[degree], df = 0;
    for (int k = degree - 1; k >= 0; --k) {
      df = df * x + f;
      f = f * x + c[k];
    }
    if (f == 0) return x;
    if ((f < 0) == (fa < 0)) {
      a = x;
      fa = f;
    } else {
      b = x;
    }
    double next = df != 0 ? x - f / df : a;
    if (!(next > a && next < b)) next = 0.5 * (a + b);  // Newton left the bracket: bisect
    if (next == x || b - a <= 0) return next;
    x = next;
  }
  return x;
}

}  // namespace

double evaluate_polynomial(const double* c, int degree, double x) {
  double f = c[degree];
  for (int k = degree - 1; k >= 0; --k) f = f * x + c[k];
  return f;
}

int polynomial_roots(const double* c, int degree, double lo, double hi, double touch_tolerance, double* roots) {
  degree = std::min(degree, kMaxPolynomialDegree);
  while (degree > 0 && c[degree] == 0) --degree;
  if (degree <= 0 || !(lo <= hi)) return 0;
  if (degree == 1) {
    double x = -c[0] / c[1];
    if (!(x >= lo && x <= hi)) return 0;
    roots[0] = x;
    return 1;
  }
  // The derivative's roots are the critical points; between two of them c is monotone.
  double derivative[kMaxPolynomialDegree];
  for (int k = 1; k <= degree; ++k) derivative[k - 1] = k * c[k];
  double breaks[kMaxPolynomialDegree + 1];
  int nbreaks = 0;
  breaks[nbreaks++] = lo;
  double critical[kMaxPolynomialDegree];
  int ncritical = polynomial_roots(derivative, degree - 1, lo, hi, 0.0, critical);
  for (int i = 0; i < ncritical; ++i) breaks[nbreaks++] = critical[i];
  breaks[nbreaks++] = hi;

  const double merge = kRootMergeRelative * std::max({1.0, std::abs(lo), std::abs(hi)});
  int count = 0;
  auto add = [&](double x) {
    if (count > 0 && x - roots[count - 1] <= merge) return;
    if (count < degree) roots[count++] = x;
  };
  double f[kMaxPolynomialDegree + 1];
  for (int i = 0; i < nbreaks; ++i) f[i] = evaluate_polynomial(c, degree, breaks[i]);
  auto sign_change = [&](int i) { return f[i] != 0 && f[i + 1] != 0 && (f[i] < 0) != (f[i + 1] < 0); };
  for (int i = 0; i < nbreaks; ++i) {
    if (i > 0 && sign_change(i - 1)) add(bracketed_root(c, degree, breaks[i - 1], breaks[i], f[i - 1]));
    // An exact zero at a breakpoint, or a touching root: a critical point whose value is within
    // the tolerance of zero and around which c keeps its sign (else the sign changes find it).
    bool interior = i > 0 && i + 1 < nbreaks;
    bool touches = interior && std::abs(f[i]) <= touch_tolerance && !sign_change(i - 1) && !sign_change(i);
    if (f[i] == 0 || touches) add(breaks[i]);
  }
  return count;
}

}  // namespace darc
