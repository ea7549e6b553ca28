#include "core/footprint/sphere_coverage.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace darc {

namespace {

// Q(u, v) = c + cu u + cv v + cuu u^2 + cuv u v + cvv v^2: the sub-ray (u, v) meets the sphere
// where Q >= 0.
struct Quadratic {
  double c = 0, cu = 0, cv = 0, cuu = 0, cuv = 0, cvv = 0;
  double at(double u, double v) const { return c + u * (cu + cuu * u + cuv * v) + v * (cv + cvv * v); }
};

// r^2 P(u, v) - |w0 + wu u + wv v|^2, with P = p + pu u + pv v + puu u^2 + puv u v + pvv v^2.
Quadratic silhouette(double r2, const Quadratic& p, const Vec3d& w0, const Vec3d& wu, const Vec3d& wv) {
  Quadratic q;
  q.c = r2 * p.c - dot(w0, w0);
  q.cu = r2 * p.cu - 2 * dot(w0, wu);
  q.cv = r2 * p.cv - 2 * dot(w0, wv);
  q.cuu = r2 * p.cuu - dot(wu, wu);
  q.cuv = r2 * p.cuv - 2 * dot(wu, wv);
  q.cvv = r2 * p.cvv - dot(wv, wv);
  return q;
}

// Silhouettes whose quadratic part is this close to singular (relative) are not ellipses one
// can trust (the sphere seen almost along the footprint's plane): the sub-ray tests take them.
constexpr double kSingularEllipse = 1e-12;

}  // namespace

double unit_disc_area_in_polygon(const double (*p)[2], int n) {
  auto cross = [](const double* a, const double* b) { return a[0] * b[1] - a[1] * b[0]; };
  auto sector = [&](const double* a, const double* b) {
    return 0.5 * std::atan2(cross(a, b), a[0] * b[0] + a[1] * b[1]);
  };
  double area = 0;
  for (int i = 0; i < n; ++i) {
    const double* a = p[i];
    const double* b = p[(i + 1) % n];
    // The edge a + (b - a) s, s in [0, 1], against |x| = 1: inside between the roots s1 <= s2.
    const double e[2] = {b[0] - a[0], b[1] - a[1]};
    const double ee = e[0] * e[0] + e[1] * e[1];
    if (!(ee > 0)) continue;
    const double ae = a[0] * e[0] + a[1] * e[1];
    const double disc = ae * ae - ee * (a[0] * a[0] + a[1] * a[1] - 1);
    double s1 = 1, s2 = 1;  // no part inside: the whole edge is a sector
    if (disc > 0) {
      const double root = std::sqrt(disc);
      s1 = std::clamp((-ae - root) / ee, 0.0, 1.0);
      s2 = std::clamp((-ae + root) / ee, 0.0, 1.0);
    }
    if (s1 >= s2) {
      area += sector(a, b);
      continue;
    }
    const double p1[2] = {a[0] + e[0] * s1, a[1] + e[1] * s1};
    const double p2[2] = {a[0] + e[0] * s2, a[1] + e[1] * s2};
    area += sector(a, p1) + 0.5 * cross(p1, p2) + sector(p2, b);
  }
  return std::abs(area);
}

SphereCoverage sphere_coverage(const FootprintFrame& frame, const Vec3d& centre, double radius,
                               SphereFootprintHit& hit) {
  if (!(radius > 0) || !std::isfinite(radius)) return SphereCoverage::NotAnalytic;
  const double r2 = radius * radius;
  Quadratic q;
  double t_lo = 0, t_hi = 0;
  Vec3d a;  // pencil: from the apex to the centre (the nappe test)
  if (frame.form == FootprintForm::Pencil) {
    // Q = r^2 |D|^2 - |D x a|^2 (Lagrange's identity turns (D.a)^2 - (|a|^2 - r^2)|D|^2 into a
    // form without the cancellation of two nearly equal squares for a small, far sphere).
    a = centre - frame.apex;
    const double distance = length(a);
    if (!(distance > radius)) return SphereCoverage::NotAnalytic;  // the apex inside the sphere
    const Quadratic p{dot(frame.d, frame.d),         2 * dot(frame.d, frame.ddx), 2 * dot(frame.d, frame.ddy),
                      dot(frame.ddx, frame.ddx),     2 * dot(frame.ddx, frame.ddy), dot(frame.ddy, frame.ddy)};
    q = silhouette(r2, p, cross(frame.d, a), cross(frame.ddx, a), cross(frame.ddy, a));
    // The sphere lies between |a| - r and |a| + r from the apex; the sub-rays' directions are
    // between these lengths.
    const double spread = 0.5 * (length(frame.ddx) + length(frame.ddy));
    const double d_min = length(frame.d) - spread, d_max = length(frame.d) + spread;
    if (!(d_min > 0)) return SphereCoverage::NotAnalytic;
    const double s_lo = (distance - radius) / d_max, s_hi = (distance + radius) / d_min;
    if (frame.side > 0) {
      t_lo = frame.apex_t + s_lo, t_hi = frame.apex_t + s_hi;
    } else {
      t_lo = frame.apex_t - s_hi, t_hi = frame.apex_t - s_lo;
    }
  } else {
    const Vec3d c = centre - frame.o;
    const Quadratic p{dot(frame.d, frame.d), 0, 0, 0, 0, 0};
    q = silhouette(r2, p, cross(c, frame.d), -cross(frame.dox, frame.d), -cross(frame.doy, frame.d));
    const double dd = p.c;
    const double t_centre = dot(c, frame.d) / dd;
    const double slack = radius / std::sqrt(dd) + 0.5 * (std::abs(dot(frame.dox, frame.d)) + std::abs(dot(frame.doy, frame.d))) / dd;
    t_lo = t_centre - slack, t_hi = t_centre + slack;
  }
  if (!std::isfinite(t_lo) || !std::isfinite(t_hi)) return SphereCoverage::NotAnalytic;
  if (t_hi <= frame.t_min || t_lo >= frame.t_max) return SphereCoverage::Miss;
  if (t_lo <= frame.t_min || t_hi >= frame.t_max) return SphereCoverage::NotAnalytic;

  // Inside: Q >= 0, an ellipse when the quadratic part M = [[cuu, cuv/2], [cuv/2, cvv]] is
  // negative definite.
  const double m11 = q.cuu, m12 = 0.5 * q.cuv, m22 = q.cvv;
  const double det = m11 * m22 - m12 * m12;
  if (!(m11 < 0) || !(det > kSingularEllipse * m11 * m22)) return SphereCoverage::NotAnalytic;
  // Its centre m solves M m = -(cu, cv) / 2; Q there is its largest value K.
  const double mu = -(m22 * 0.5 * q.cu - m12 * 0.5 * q.cv) / det;
  const double mv = -(m11 * 0.5 * q.cv - m12 * 0.5 * q.cu) / det;
  const double k = q.c + 0.5 * (q.cu * mu + q.cv * mv);
  if (!(k > 0)) return SphereCoverage::Miss;
  if (frame.form == FootprintForm::Pencil && !(double(frame.side) * dot(frame.direction(mu, mv), a) > 0))
    return SphereCoverage::Miss;  // the silhouette of the other nappe: the sphere is behind
  // (x - m)^T N (x - m) <= 1 with N = -M / K = L L^T; y = L^T (x - m) maps it onto the unit disc.
  const double n11 = -m11 / k, n12 = -m12 / k, n22 = -m22 / k;
  const double l11 = std::sqrt(n11), l21 = n12 / l11, l22 = std::sqrt(std::max(0.0, n22 - l21 * l21));
  if (!(l22 > 0) || !std::isfinite(l11) || !std::isfinite(l22)) return SphereCoverage::NotAnalytic;
  const double jacobian = l11 * l22;  // area in y = area in (u, v) times this
  // The ellipse's box: half extents sqrt((N^-1)_uu) and sqrt((N^-1)_vv).
  const double det_n = n11 * n22 - n12 * n12;
  const double eu = std::sqrt(n22 / det_n), ev = std::sqrt(n11 / det_n);
  if (mu - eu >= 0.5 || mu + eu <= -0.5 || mv - ev >= 0.5 || mv + ev <= -0.5) return SphereCoverage::Miss;
  double area;
  if (mu - eu >= -0.5 && mu + eu <= 0.5 && mv - ev >= -0.5 && mv + ev <= 0.5) {
    area = std::numbers::pi / jacobian;  // the whole ellipse lies in the footprint
  } else if (q.at(-0.5, -0.5) >= 0 && q.at(0.5, -0.5) >= 0 && q.at(0.5, 0.5) >= 0 && q.at(-0.5, 0.5) >= 0) {
    area = 1;  // a convex region holding the square's corners holds the square
  } else {
    double corners[4][2];
    const double cu[4] = {-0.5, 0.5, 0.5, -0.5}, cv[4] = {-0.5, -0.5, 0.5, 0.5};
    for (int i = 0; i < 4; ++i) {
      const double du = cu[i] - mu, dv = cv[i] - mv;
      corners[i][0] = l11 * du + l21 * dv;
      corners[i][1] = l22 * dv;
    }
    area = unit_disc_area_in_polygon(corners, 4) / jacobian;
  }
  const float coverage = float(std::min(area, 1.0));
  if (!(coverage > 0)) return SphereCoverage::Miss;

  CoverageMask mask = 0;
  double nearest = std::numeric_limits<double>::infinity();
  int nearest_point = -1;
  for (int b = 0; b < kMaskSide * kMaskSide; ++b) {
    const double u = mask_point_u(b), v = mask_point_v(b);
    if (q.at(u, v) < 0) continue;
    mask |= CoverageMask{1} << b;
    const double d2 = (u - mu) * (u - mu) + (v - mv) * (v - mv);
    if (d2 < nearest) nearest = d2, nearest_point = b;
  }
  hit.coverage = coverage;
  hit.mask = mask;
  hit.t_near = float(t_lo);
  hit.t_far = float(t_hi);
  hit.covers_centre = q.c >= 0;
  if (hit.covers_centre) {
    hit.u = hit.v = 0;
  } else {
    const double cu = std::clamp(mu, -0.5, 0.5), cv = std::clamp(mv, -0.5, 0.5);
    if (q.at(cu, cv) >= 0 || nearest_point < 0) {
      hit.u = float(cu), hit.v = float(cv);
    } else {
      hit.u = mask_point_u(nearest_point), hit.v = mask_point_v(nearest_point);
    }
  }
  return SphereCoverage::Covered;
}

}  // namespace darc
