#include "core/geometry/surfaces/quadric.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "core/math/polynomial_roots.h"

namespace darc {

namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;
constexpr double kRadiansPerDegree = std::numbers::pi / 180.0;
// Relative outward padding of the float bounds, so that rounding the double-precision corners
// to float never cuts off the surface (a few float ulps, as for the sphere).
constexpr float kBoundsRelativePadding = 4.0f * std::numeric_limits<float>::epsilon();

bool finite(double x) { return std::isfinite(x); }
bool finite(const Vec3d& p) { return finite(p.x) && finite(p.y) && finite(p.z); }

double sweep_radians(double degrees) { return std::clamp(degrees, -360.0, 360.0) * kRadiansPerDegree; }

// Places `angle` in the range swept from `start` by the signed `span` (|span| <= 2 pi), modulo
// 2 pi, and writes its fraction of the span (0 at start, 1 at start + span). Returns false when
// `clip` is set and the angle lies in the part a partial sweep cuts away.
bool angle_fraction(double angle, double start, double span, bool clip, double& fraction) {
  double lo = std::min(start, start + span);
  double offset = std::fmod(angle - lo, kTwoPi);
  if (offset < 0) offset += kTwoPi;
  if (clip && std::abs(span) < kTwoPi && offset > std::abs(span)) return false;
  fraction = std::clamp((lo + offset - start) / span, 0.0, 1.0);
  return true;
}

// [lo, hi] clipping for the axial parameter; without `clip` every point passes.
bool within(double x, double lo, double hi, bool clip) { return !clip || (x >= lo && x <= hi); }

// The torus is solved in a frame scaled so that its bounding sphere has radius 1 and centred on
// the ray point nearest the torus centre: the quartic's coefficients are then O(1) whatever the
// torus size or the ray origin. The sphere is padded by this much so that grazing roots on it
// are kept.
constexpr double kTorusFramePadding = 1e-9;
// A critical point of the quartic whose value is within this of zero is a touching root (a
// tangent ray at the silhouette). In the unit frame the quartic's rounding error is ~1e-15, and
// a ray passing the torus at scaled distance delta has |F| ~ |grad F| delta, so this keeps
// tangent rays without hitting rays that miss by more than ~1e-12 of the torus size.
constexpr double kTorusTouchTolerance = 1e-12;
// A point is on the other branch of the parametrization (theta + pi, the inner lemon of a
// spindle torus) only within this distance, relative to the torus size, of that branch's circle.
constexpr double kTorusBranchTolerance = 1e-6;

}  // namespace

// ---- Builders --------------------------------------------------------------------------------

void Quadric::finish(const Matrix4& object_to_world_in, bool nondegenerate_shape) {
  object_to_world = object_to_world_in;
  bool invertible = object_to_world.inverse(world_to_object);
  degenerate = !nondegenerate_shape || thetamax == 0 || !finite(thetamax) || !invertible;
}

Quadric Quadric::cone(double height_rib, double radius_rib, double thetamax_degrees, const Matrix4& m) {
  // Height 0 puts every point in the plane z = 0 with the Disk's parametrization and normal.
  if (height_rib == 0) return disk(0, radius_rib, thetamax_degrees, m);
  Quadric q;
  q.kind = QuadricKind::Cone;
  q.height = height_rib;
  q.radius = radius_rib;
  q.thetamax = sweep_radians(thetamax_degrees);
  // rho = radius (1 - w) with w = z / height, the spec's v.
  q.w_scale = height_rib;
  q.rho2_a = radius_rib * radius_rib;
  q.rho2_b = -2 * radius_rib * radius_rib;
  q.rho2_c = radius_rib * radius_rib;
  q.z_lo = std::min(0.0, height_rib);
  q.z_hi = std::max(0.0, height_rib);
  bool ok = finite(height_rib) && finite(radius_rib) && finite(thetamax_degrees) && radius_rib != 0;
  q.finish(m, ok);
  return q;
}

Quadric Quadric::cylinder(double radius_rib, double zmin_rib, double zmax_rib, double thetamax_degrees,
                          const Matrix4& m) {
  Quadric q;
  q.kind = QuadricKind::Cylinder;
  q.radius = radius_rib;
  q.zmin = zmin_rib;
  q.zmax = zmax_rib;
  q.thetamax = sweep_radians(thetamax_degrees);
  q.rho2_c = radius_rib * radius_rib;  // w = z, rho constant
  q.z_lo = std::min(zmin_rib, zmax_rib);
  q.z_hi = std::max(zmin_rib, zmax_rib);
  bool ok = finite(radius_rib) && finite(zmin_rib) && finite(zmax_rib) && finite(thetamax_degrees) && radius_rib != 0 &&
            zmin_rib != zmax_rib;
  q.finish(m, ok);
  return q;
}

Quadric Quadric::disk(double height_rib, double radius_rib, double thetamax_degrees, const Matrix4& m) {
  Quadric q;
  q.kind = QuadricKind::Disk;
  q.height = height_rib;
  q.radius = radius_rib;
  q.thetamax = sweep_radians(thetamax_degrees);
  q.flat = true;
  q.z_lo = q.z_hi = height_rib;
  bool ok = finite(height_rib) && finite(radius_rib) && finite(thetamax_degrees) && radius_rib != 0;
  q.finish(m, ok);
  return q;
}

Quadric Quadric::paraboloid(double rmax_rib, double zmin_rib, double zmax_rib, double thetamax_degrees,
                            const Matrix4& m) {
  Quadric q;
  q.kind = QuadricKind::Paraboloid;
  q.radius = rmax_rib;
  q.zmin = zmin_rib;
  q.zmax = zmax_rib;
  q.thetamax = sweep_radians(thetamax_degrees);
  // rho^2 = rmax^2 w with w = z / zmax.
  q.w_scale = zmax_rib;
  q.rho2_b = rmax_rib * rmax_rib;
  // Only the side of z = 0 that zmax is on has points (z / zmax >= 0).
  double z0 = zmax_rib > 0 ? std::max(0.0, zmin_rib) : std::min(0.0, zmin_rib);
  q.z_lo = std::min(z0, zmax_rib);
  q.z_hi = std::max(z0, zmax_rib);
  bool ok = finite(rmax_rib) && finite(zmin_rib) && finite(zmax_rib) && finite(thetamax_degrees) && rmax_rib != 0 &&
            zmax_rib != 0 && zmin_rib != zmax_rib && q.z_lo < q.z_hi;
  q.finish(m, ok);
  return q;
}

Quadric Quadric::hyperboloid(const Vec3d& p1, const Vec3d& p2, double thetamax_degrees, const Matrix4& m) {
  Quadric q;
  q.kind = QuadricKind::Hyperboloid;
  q.point1 = p1;
  q.point2 = p2;
  q.thetamax = sweep_radians(thetamax_degrees);
  Vec3d d = p2 - p1;
  q.z_lo = std::min(p1.z, p2.z);
  q.z_hi = std::max(p1.z, p2.z);
  q.flat = d.z == 0;
  // |(p1 + w d)_xy|^2 with w = (z - p1.z) / d.z, the spec's v.
  q.w_origin = p1.z;
  q.w_scale = q.flat ? 1.0 : d.z;
  q.rho2_a = d.x * d.x + d.y * d.y;
  q.rho2_b = 2 * (p1.x * d.x + p1.y * d.y);
  q.rho2_c = p1.x * p1.x + p1.y * p1.y;
  // Zero area when the points coincide or the segment lies on the axis.
  bool off_axis = q.rho2_c > 0 || (p2.x * p2.x + p2.y * p2.y) > 0;
  bool ok = finite(p1) && finite(p2) && finite(thetamax_degrees) && p1 != p2 && off_axis;
  q.finish(m, ok);
  return q;
}

Quadric Quadric::torus(double major_rib, double minor_rib, double phimin_degrees, double phimax_degrees,
                       double thetamax_degrees, const Matrix4& m) {
  Quadric q;
  q.kind = QuadricKind::Torus;
  q.major_radius = major_rib;
  q.radius = minor_rib;
  double span = std::clamp(phimax_degrees - phimin_degrees, -360.0, 360.0);
  q.phimin = phimin_degrees * kRadiansPerDegree;
  q.phimax = (phimin_degrees + span) * kRadiansPerDegree;
  q.thetamax = sweep_radians(thetamax_degrees);
  q.z_lo = -std::abs(minor_rib);
  q.z_hi = std::abs(minor_rib);
  bool ok = finite(major_rib) && finite(minor_rib) && finite(phimin_degrees) && finite(phimax_degrees) &&
            finite(thetamax_degrees) && minor_rib != 0 && span != 0;
  q.finish(m, ok);
  return q;
}

// ---- Bounds ----------------------------------------------------------------------------------

BBox Quadric::bounds() const {
  BBox box;
  if (degenerate) return box;
  double rho_max = std::abs(radius);
  if (kind == QuadricKind::Paraboloid) rho_max *= std::sqrt(std::max(1.0, zmin / zmax));
  if (kind == QuadricKind::Hyperboloid) {
    rho_max = std::sqrt(std::max(point1.x * point1.x + point1.y * point1.y, point2.x * point2.x + point2.y * point2.y));
  }
  if (kind == QuadricKind::Torus) rho_max = std::abs(major_radius) + std::abs(radius);
  for (int corner = 0; corner < 8; ++corner) {
    Vec3d p{(corner & 1) ? rho_max : -rho_max, (corner & 2) ? rho_max : -rho_max, (corner & 4) ? z_hi : z_lo};
    box.extend(Vec3f(object_to_world.transform_point(p)));
  }
  Vec3f magnitude = max(abs(box.lo), abs(box.hi));
  return box.expanded(kBoundsRelativePadding * max_component(magnitude));
}

// ---- Intersection ----------------------------------------------------------------------------

int Quadric::implicit_roots(const Vec3d& o_in, const Vec3d& d, double roots[4]) const {
  if (kind == QuadricKind::Torus) return torus_roots(o_in, d, roots);
  if (flat) {
    if (d.z == 0) return 0;
    roots[0] = (z_lo - o_in.z) / d.z;
    return 1;
  }
  // Solve from the ray point nearest the middle of the axis segment: the coefficients are then
  // of the size of the surface, not of the ray origin's distance (no cancellation for far rays).
  double dd = dot(d, d);
  double t_shift = dot(Vec3d{0, 0, 0.5 * (z_lo + z_hi)} - o_in, d) / dd;
  Vec3d o = o_in + d * t_shift;
  // x^2 + y^2 - rho^2(w) along the ray, with w = w0 + t w1: a t^2 + 2 b t + c = 0.
  double w0 = (o.z - w_origin) / w_scale, w1 = d.z / w_scale;
  double a = d.x * d.x + d.y * d.y - rho2_a * w1 * w1;
  double b = o.x * d.x + o.y * d.y - (rho2_a * w0 * w1 + 0.5 * rho2_b * w1);
  double c = o.x * o.x + o.y * o.y - ((rho2_a * w0 + rho2_b) * w0 + rho2_c);
  double discriminant = b * b - a * c;
  if (!(discriminant >= 0)) return 0;
  // q has the sign of -b, so it never cancels; the other root is c / q (product of the roots).
  double q = -(b + std::copysign(std::sqrt(discriminant), b));
  int n = 0;
  if (q == 0) {
    if (a != 0) roots[n++] = t_shift;  // tangent at the shifted origin: a double root at 0
    return n;
  }
  for (double t : {q / a, c / q}) {
    if (finite(t)) roots[n++] = t + t_shift;  // q / a is infinite when the equation is linear
  }
  if (n == 2 && roots[0] > roots[1]) std::swap(roots[0], roots[1]);
  return n;
}

bool Quadric::intersect(const Ray& ray, SurfaceHit& hit) const {
  if (degenerate) return false;
  Vec3d o = world_to_object.transform_point(Vec3d(ray.o));
  Vec3d d = world_to_object.transform_vector(Vec3d(ray.d));
  double dd = dot(d, d);
  if (!(dd > 0) || !std::isfinite(dd) || !finite(o)) return false;  // zero or NaN ray
  double roots[4];
  int n = implicit_roots(o, d, roots);
  for (int i = 0; i < n; ++i) {
    double t = roots[i];
    if (!(t > double(ray.tmin) && t < double(ray.tmax))) continue;
    Vec3d p = o + d * t;
    SurfacePoint sp;
    if (!locate(p, true, sp)) continue;
    Vec3d n_world = normalize(world_to_object.transform_normal_by_inverse(sp.normal));
    hit.t = float(t);
    hit.p = Vec3f(object_to_world.transform_point(p));
    hit.ng = Vec3f(n_world);
    hit.u = float(sp.u);
    hit.v = float(sp.v);
    return true;
  }
  return false;
}

Vec2f Quadric::parameters_at(const Vec3f& p_world) const {
  SurfacePoint sp;
  locate(world_to_object.transform_point(Vec3d(p_world)), false, sp);
  return {float(sp.u), float(sp.v)};
}

Vec3f Quadric::normal_at(const Vec3f& p_world) const {
  SurfacePoint sp;
  locate(world_to_object.transform_point(Vec3d(p_world)), false, sp);
  return Vec3f(normalize(world_to_object.transform_normal_by_inverse(sp.normal)));
}

// ---- Surface coordinates and parametric normals -----------------------------------------------

bool Quadric::locate(const Vec3d& p, bool clip, SurfacePoint& out) const {
  // Where the parametric normal vanishes (a cone's apex, the disk's centre, a hyperboloid point
  // on the axis) any direction is as good; the axis keeps it a unit vector.
  out.normal = {0, 0, 1};
  if (kind == QuadricKind::Torus) return locate_torus(p, clip, out);
  double alpha = std::atan2(p.y, p.x);
  double rho = std::sqrt(p.x * p.x + p.y * p.y);
  Vec3d n;
  if (kind == QuadricKind::Hyperboloid) {
    Vec3d d = point2 - point1;
    double v = 0;
    if (!flat) {
      if (!within(p.z, z_lo, z_hi, clip)) return false;
      v = (p.z - point1.z) / d.z;
    } else {
      // rho^2 = a v^2 + b v + c: the smallest v in [0, 1] on the segment (a segment through its
      // closest approach to the axis covers the inner rings twice; the first pass is kept).
      double a = rho2_a, b = rho2_b, c = rho2_c - rho * rho;
      double disc = std::max(0.0, b * b - 4 * a * c);
      double q = -0.5 * (b + std::copysign(std::sqrt(disc), b));
      double best = std::numeric_limits<double>::infinity();
      for (double candidate : {a != 0 ? q / a : best, q != 0 ? c / q : best}) {
        if (candidate >= -1e-9 && candidate <= 1 + 1e-9) best = std::min(best, candidate);
      }
      if (!finite(best)) {
        if (clip) return false;
        best = 0;
      }
      v = best;
    }
    out.v = std::clamp(v, 0.0, 1.0);
    Vec3d line = point1 + d * out.v;
    double theta = alpha - std::atan2(line.y, line.x);
    if (!angle_fraction(theta, 0, thetamax, clip, out.u)) return false;
    // dP/du = thetamax (-y, x, 0), dP/dv = the segment direction rotated by theta.
    double th = out.u * thetamax, ct = std::cos(th), st = std::sin(th);
    Vec3d dpdv{ct * d.x - st * d.y, st * d.x + ct * d.y, d.z};
    n = cross(Vec3d{-p.y, p.x, 0} * thetamax, dpdv);
  } else {
    // The others put a point of signed radius r at angle theta; r < 0 lands half a turn away.
    double theta = radius < 0 ? alpha + std::numbers::pi : alpha;
    if (!angle_fraction(theta, 0, thetamax, clip, out.u)) return false;
    switch (kind) {
      case QuadricKind::Cylinder:  // thetamax (zmax - zmin) (x, y, 0)
        if (!within(p.z, z_lo, z_hi, clip)) return false;
        out.v = (p.z - zmin) / (zmax - zmin);
        n = Vec3d{p.x, p.y, 0} * (thetamax * (zmax - zmin));
        break;
      case QuadricKind::Cone:  // thetamax (height x, height y, radius^2 (1 - v))
        out.v = p.z / height;
        if (!within(out.v, 0, 1, clip)) return false;
        n = Vec3d{height * p.x, height * p.y, radius * radius * (1 - out.v)} * thetamax;
        break;
      case QuadricKind::Disk:  // thetamax radius^2 (1 - v) (0, 0, 1)
        out.v = 1 - rho / std::abs(radius);
        if (!within(out.v, 0, 1, clip)) return false;
        n = Vec3d{0, 0, thetamax};
        break;
      default:  // Paraboloid: thetamax (zmax - zmin) (x, y, -rmax^2 / (2 zmax))
        if (!within(p.z, z_lo, z_hi, clip)) return false;
        out.v = (p.z - zmin) / (zmax - zmin);
        n = Vec3d{p.x, p.y, -radius * radius / (2 * zmax)} * (thetamax * (zmax - zmin));
        break;
    }
  }
  out.v = std::clamp(out.v, 0.0, 1.0);
  if (length_squared(n) > 0 && finite(n)) out.normal = n;
  return true;
}

// ---- Torus ---------------------------------------------------------------------------------

int Quadric::torus_roots(const Vec3d& o, const Vec3d& d, double roots[4]) const {
  // F = (|p|^2 + R^2 - r^2)^2 - 4 R^2 (x^2 + y^2) in the unit frame: p = c + tau e with e the
  // unit direction and c the ray point nearest the centre (so c . e = 0 and |p|^2 = tau^2 + |c|^2).
  double scale = 1 / (std::abs(major_radius) + std::abs(radius));
  double length_d = length(d);
  Vec3d e = d / length_d;
  Vec3d o_scaled = o * scale;
  double t_centre = -dot(o_scaled, e);
  Vec3d c = o_scaled + e * t_centre;
  double c2 = dot(c, c);
  double reach2 = (1 + kTorusFramePadding) * (1 + kTorusFramePadding) - c2;
  if (!(reach2 >= 0)) return 0;
  double reach = std::sqrt(reach2);
  double R2 = major_radius * major_radius * scale * scale;
  double k = c2 + R2 - radius * radius * scale * scale;
  double coefficients[5] = {
      k * k - 4 * R2 * (c.x * c.x + c.y * c.y),
      -8 * R2 * (c.x * e.x + c.y * e.y),
      2 * k - 4 * R2 * (e.x * e.x + e.y * e.y),
      0,
      1,
  };
  double tau[4];
  int n = polynomial_roots(coefficients, 4, -reach, reach, kTorusTouchTolerance, tau);
  for (int i = 0; i < n; ++i) roots[i] = (t_centre + tau[i]) / (scale * length_d);
  return n;
}

bool Quadric::locate_torus(const Vec3d& p, bool clip, SurfacePoint& out) const {
  // A point at distance rho from the axis is either at theta = its own angle with
  // major + minor cos phi = rho, or at theta + pi with major + minor cos phi = -rho. The branch
  // whose tube circle passes nearer the point comes first; the other counts only when the point
  // is on its circle too (a spindle torus, major < minor, covers its inner lemon twice).
  double alpha = std::atan2(p.y, p.x);
  double rho = std::sqrt(p.x * p.x + p.y * p.y);
  struct Branch {
    double theta, q, residual;  // q = minor cos phi
  } branches[2];
  for (int side = 0; side < 2; ++side) {
    double q = (side == 0 ? rho : -rho) - major_radius;
    branches[side] = {side == 0 ? alpha : alpha + std::numbers::pi, q, std::abs(std::hypot(q, p.z) - std::abs(radius))};
  }
  if (branches[1].residual < branches[0].residual) std::swap(branches[0], branches[1]);
  double tolerance = kTorusBranchTolerance * (std::abs(major_radius) + std::abs(radius));
  for (int i = 0; i < 2; ++i) {
    const Branch& b = branches[i];
    if (i == 1 && b.residual > tolerance) break;
    double phi = std::atan2(p.z / radius, b.q / radius);
    SurfacePoint sp;
    if (!angle_fraction(b.theta, 0, thetamax, clip, sp.u)) continue;
    if (!angle_fraction(phi, phimin, phimax - phimin, clip, sp.v)) continue;
    // dP/du x dP/dv = thetamax (phimax - phimin) minor (major + minor cos phi) (cos phi cos theta,
    // cos phi sin theta, sin phi), with theta and phi the swept angles the fractions stand for.
    double theta = sp.u * thetamax, phi_swept = phimin + sp.v * (phimax - phimin);
    double cp = std::cos(phi_swept), sp_ = std::sin(phi_swept);
    double factor = thetamax * (phimax - phimin) * radius * (major_radius + radius * cp);
    Vec3d n = Vec3d{cp * std::cos(theta), cp * std::sin(theta), sp_} * factor;
    out.u = sp.u;
    out.v = sp.v;
    if (length_squared(n) > 0 && finite(n)) out.normal = n;
    return true;
  }
  return false;
}

}  // namespace darc
