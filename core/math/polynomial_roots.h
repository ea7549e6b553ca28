// Real roots of low-degree polynomials (degree <= 4) inside an interval, in double precision,
// by root isolation rather than closed-form radicals: the derivative's roots split the interval
// into pieces on which the polynomial is monotone, and each piece with a sign change holds
// exactly one root, found by safeguarded Newton iteration. A touching (double) root, where the
// polynomial reaches zero at a critical point without changing sign, counts when its value is
// within a caller-given tolerance of zero. Used by the torus (a quartic) so that rays grazing
// the silhouette, where Ferrari's closed form loses most of its digits, still hit.
#pragma once

namespace darc {

// The largest degree polynomial_roots accepts (the torus quartic).
inline constexpr int kMaxPolynomialDegree = 4;

// Evaluates c[0] + c[1] x + ... + c[degree] x^degree (Horner).
double evaluate_polynomial(const double* c, int degree, double x);

// Writes the real roots of c[0] + ... + c[degree] x^degree in [lo, hi] to roots[] in ascending
// order (at most `degree` of them, near-duplicates merged) and returns their count. A critical
// point where |p| <= touch_tolerance counts as a root. degree is clamped to kMaxPolynomialDegree
// and lowered while the leading coefficient is zero; a zero polynomial has no roots.
int polynomial_roots(const double* c, int degree, double lo, double hi, double touch_tolerance, double* roots);

}  // namespace darc
