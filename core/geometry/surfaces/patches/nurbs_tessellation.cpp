#include "core/geometry/surfaces/patches/nurbs_tessellation.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace darc {

namespace {

bool validate_direction(const NurbsDirection& d, char name, std::string& error) {
  if (d.order < 1 || d.order > kMaxNurbsOrder) {
    error = fmt::format("{}order must be 1 to {}, found {}", name, kMaxNurbsOrder, d.order);
    return false;
  }
  if (d.n < d.order) {
    error = fmt::format("n{} = {} control points are fewer than the {}order {}", name, d.n, name, d.order);
    return false;
  }
  const size_t expected = size_t(d.n) + size_t(d.order);
  if (d.knots.size() != expected) {
    error = fmt::format("{}knot needs n{} + {}order = {} values, found {}", name, name, name, expected, d.knots.size());
    return false;
  }
  for (size_t k = 0; k < d.knots.size(); ++k) {
    if (!std::isfinite(d.knots[k])) {
      error = fmt::format("{}knot value {} is not finite", name, k);
      return false;
    }
    if (k > 0 && d.knots[k] < d.knots[k - 1]) {
      error = fmt::format("{}knot decreases at value {} ({} after {})", name, k, d.knots[k], d.knots[k - 1]);
      return false;
    }
  }
  // Outside [knot[order-1], knot[n]] fewer than order basis functions overlap: no surface there.
  const double lo = d.knots[size_t(d.order - 1)], hi = d.knots[size_t(d.n)];
  if (!(d.min < d.max) || d.min < lo || d.max > hi) {
    error = fmt::format("{0}min {1} and {0}max {2} must satisfy {3} <= {0}min < {0}max <= {4} (the knots' range)", name,
                        d.min, d.max, lo, hi);
    return false;
  }
  return true;
}

// The knot interval [knots[k], knots[k+1]] (non-empty, order - 1 <= k <= n - 1) that holds t;
// at the domain's end, the last non-empty one.
int knot_interval(const NurbsDirection& d, double t) {
  const auto first = d.knots.begin() + (d.order - 1), last = d.knots.begin() + d.n;
  int k = int(std::upper_bound(first, last, t) - d.knots.begin()) - 1;
  k = std::clamp(k, d.order - 1, d.n - 1);
  while (k > d.order - 1 && !(d.knots[size_t(k)] < d.knots[size_t(k) + 1])) --k;
  return k;
}

// The order nonzero basis functions N_{k-p..k, p} at t of interval k (p = order - 1) and their
// derivatives, by the Cox-de Boor recurrence in the triangular form of Piegl and Tiller (The
// NURBS Book, A2.2); the derivative of N_{m,p} is p N_{m,p-1} / (t_{m+p} - t_m) - p N_{m+1,p-1}
// / (t_{m+p+1} - t_{m+1}) from the degree p - 1 functions, kept on the way.
struct BasisValues {
  double N[kMaxNurbsOrder], dN[kMaxNurbsOrder];
};

void basis_functions(const NurbsDirection& d, int k, double t, BasisValues& out) {
  const int p = d.order - 1;
  const std::vector<double>& U = d.knots;
  double left[kMaxNurbsOrder], right[kMaxNurbsOrder], lower[kMaxNurbsOrder];
  double* N = out.N;
  N[0] = 1;
  lower[0] = 1;
  for (int j = 1; j <= p; ++j) {
    if (j == p) std::copy(N, N + p, lower);  // the degree p - 1 functions
    left[j] = t - U[size_t(k + 1 - j)];
    right[j] = U[size_t(k + j)] - t;
    double saved = 0;
    for (int r = 0; r < j; ++r) {
      // Never 0: both knots bracket interval k, which is non-empty.
      const double temp = N[r] / (right[r + 1] + left[j - r]);
      N[r] = saved + right[r + 1] * temp;
      saved = left[j - r] * temp;
    }
    N[j] = saved;
  }
  for (int r = 0; r <= p; ++r) {
    if (p == 0) {
      out.dN[r] = 0;
      continue;
    }
    // N_{m, p-1} with m = k - p + r is lower[r - 1]; N_{m+1, p-1} is lower[r].
    double dn = 0;
    const double span_a = U[size_t(k + r)] - U[size_t(k - p + r)];
    const double span_b = U[size_t(k + r + 1)] - U[size_t(k - p + r + 1)];
    if (r >= 1 && span_a > 0) dn += lower[r - 1] / span_a;
    if (r <= p - 1 && span_b > 0) dn -= lower[r] / span_b;
    out.dN[r] = p * dn;
  }
}

SurfaceSample evaluate_in_intervals(const NurbsSurfaceDescription& s, int ku, int kv, double u, double v) {
  BasisValues bu, bv;
  basis_functions(s.u, ku, u, bu);
  basis_functions(s.v, kv, v, bv);
  const int pu = s.u.order - 1, pv = s.v.order - 1;
  HomogeneousPoint H{{}, 0}, Hu{{}, 0}, Hv{{}, 0};
  for (int b = 0; b <= pv; ++b)
    for (int a = 0; a <= pu; ++a) {
      const HomogeneousPoint& p = s.points[size_t(ku - pu + a) + size_t(kv - pv + b) * size_t(s.u.n)];
      const double w = bu.N[a] * bv.N[b], du = bu.dN[a] * bv.N[b], dv = bu.N[a] * bv.dN[b];
      H.xyz += p.xyz * w, H.w += p.w * w;
      Hu.xyz += p.xyz * du, Hu.w += p.w * du;
      Hv.xyz += p.xyz * dv, Hv.w += p.w * dv;
    }
  return rational_sample(H, Hu, Hv);
}

// min, the distinct knots strictly between min and max, max.
std::vector<double> span_edges(const NurbsDirection& d) {
  std::vector<double> edges{d.min};
  for (double k : d.knots)
    if (k > edges.back() && k < d.max) edges.push_back(k);
  edges.push_back(d.max);
  return edges;
}

std::vector<int> span_intervals(const NurbsDirection& d, const std::vector<double>& edges) {
  std::vector<int> intervals(edges.size() - 1);
  for (size_t i = 0; i + 1 < edges.size(); ++i) intervals[i] = knot_interval(d, 0.5 * (edges[i] + edges[i + 1]));
  return intervals;
}

}  // namespace

bool validate_nurbs(const NurbsSurfaceDescription& s, std::string& error) {
  if (!validate_direction(s.u, 'u', error) || !validate_direction(s.v, 'v', error)) return false;
  const size_t expected = size_t(s.u.n) * size_t(s.v.n);
  if (s.points.size() != expected) {
    error = fmt::format("nu x nv = {} x {} needs {} points, found {}", s.u.n, s.v.n, expected, s.points.size());
    return false;
  }
  return valid_control_points(s.points, error);
}

SurfaceSample evaluate_nurbs(const NurbsSurfaceDescription& s, double u, double v) {
  return evaluate_in_intervals(s, knot_interval(s.u, u), knot_interval(s.v, v), u, v);
}

TriangleMeshData tessellate_nurbs(const NurbsSurfaceDescription& s, std::string& error, const DicingView* view) {
  if (!validate_nurbs(s, error)) return {};
  SpanLayout layout{span_edges(s.u), span_edges(s.v)};
  const std::vector<int> ku = span_intervals(s.u, layout.u_edges), kv = span_intervals(s.v, layout.v_edges);
  return tessellate_spans(layout, [&](int i, int j, double u, double v) {
    return evaluate_in_intervals(s, ku[size_t(i)], kv[size_t(j)], u, v);
  }, view);
}

}  // namespace darc
