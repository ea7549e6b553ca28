#include "core/geometry/surfaces/sphere.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace darc {

namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;
// Relative outward padding of the float bounds, so that rounding the double-precision corners
// to float never cuts off the surface (a few float ulps).
constexpr float kBoundsRelativePadding = 4.0f * std::numeric_limits<float>::epsilon();

double latitude(double z, double r) { return std::asin(std::clamp(z / r, -1.0, 1.0)); }

bool finite(double x) { return std::isfinite(x); }

}  // namespace

Sphere Sphere::make(double radius_rib, double zmin_rib, double zmax_rib, double thetamax_degrees,
                    const Matrix4& object_to_world_in) {
  Sphere s;
  s.object_to_world = object_to_world_in;
  if (!finite(radius_rib) || !finite(zmin_rib) || !finite(zmax_rib) || !finite(thetamax_degrees)) return s;
  double r = std::abs(radius_rib);
  s.radius = r;
  double z0 = std::clamp(zmin_rib, -r, r);
  double z1 = std::clamp(zmax_rib, -r, r);
  s.zmin = std::min(z0, z1);
  s.zmax = std::max(z0, z1);
  s.thetamax = std::clamp(thetamax_degrees, -360.0, 360.0) * (std::numbers::pi / 180.0);
  s.v_phi0 = r > 0 ? latitude(z0, r) : 0;
  s.v_phi_span = r > 0 ? latitude(z1, r) - s.v_phi0 : 0;
  s.flip_normal = ((radius_rib < 0) != (zmin_rib > zmax_rib)) != (thetamax_degrees < 0);
  bool invertible = s.object_to_world.inverse(s.world_to_object);
  s.degenerate = !(r > 0) || !(s.zmax > s.zmin) || s.thetamax == 0 || !invertible;
  return s;
}

BBox Sphere::bounds() const {
  BBox box;
  if (degenerate) return box;
  for (int corner = 0; corner < 8; ++corner) {
    Vec3d p{(corner & 1) ? radius : -radius, (corner & 2) ? radius : -radius, (corner & 4) ? zmax : zmin};
    box.extend(Vec3f(object_to_world.transform_point(p)));
  }
  Vec3f magnitude = max(abs(box.lo), abs(box.hi));
  float pad = kBoundsRelativePadding * max_component(magnitude);
  return box.expanded(pad);
}

bool Sphere::intersect(const Ray& ray, SurfaceHit& hit) const {
  if (degenerate) return false;
  Vec3d o = world_to_object.transform_point(Vec3d(ray.o));
  Vec3d d = world_to_object.transform_vector(Vec3d(ray.d));
  double a = dot(d, d);
  if (!(a > 0) || !std::isfinite(a)) return false;  // zero or NaN direction
  // Roots of a t^2 + 2 b t + c = 0. The discriminant b^2 - a c is formed from the distance of
  // the line to the centre (f is the closest point), which avoids the cancellation of b^2 - a c
  // when the origin is far away (Haines et al., Ray Tracing Gems ch. 7; pbrt-v4 Sphere).
  double b = dot(o, d);
  Vec3d f = o - d * (b / a);
  double lf = length(f);
  double discriminant = a * (radius - lf) * (radius + lf);
  if (!(discriminant >= 0)) return false;
  double c = dot(o, o) - radius * radius;
  // q has the sign of -b, so q = -b - sign(b) sqrt(disc) never cancels; the second root comes
  // from the product of the roots, c / a.
  double q = -(b + std::copysign(std::sqrt(discriminant), b));
  double t_roots[2];
  if (q == 0) {  // origin on the sphere, ray tangent there: a double root at t = 0
    t_roots[0] = t_roots[1] = 0;
  } else {
    t_roots[0] = q / a;
    t_roots[1] = c / q;
    if (t_roots[0] > t_roots[1]) std::swap(t_roots[0], t_roots[1]);
  }
  bool full_sweep = std::abs(thetamax) >= kTwoPi;
  for (double t : t_roots) {
    if (!(t > double(ray.tmin) && t < double(ray.tmax))) continue;
    Vec3d p = o + d * t;
    double lp = length(p);
    if (lp > 0) p = p * (radius / lp);  // back onto the surface, so clipping sees z <= r exactly
    if (p.z < zmin || p.z > zmax) continue;
    double theta = std::atan2(p.y, p.x);  // (-pi, pi]
    if (thetamax > 0) {
      if (theta < 0) theta += kTwoPi;  // [0, 2pi)
    } else if (theta > 0) {
      theta -= kTwoPi;  // (-2pi, 0]: a negative sweep covers [thetamax, 0]
    }
    if (!full_sweep && std::abs(theta) > std::abs(thetamax)) continue;
    Vec3d n = normalize(world_to_object.transform_normal_by_inverse(p));
    if (flip_normal) n = -n;
    hit.t = float(t);
    hit.p = Vec3f(object_to_world.transform_point(p));
    hit.ng = Vec3f(n);
    hit.u = float(std::clamp(theta / thetamax, 0.0, 1.0));
    hit.v = float(std::clamp((latitude(p.z, radius) - v_phi0) / v_phi_span, 0.0, 1.0));
    return true;
  }
  return false;
}

bool Sphere::whole_ball(Vec3d& centre, double& world_radius) const {
  if (degenerate || std::abs(thetamax) < kTwoPi || zmin > -radius || zmax < radius) return false;
  const auto& m = object_to_world.m;
  if (m[0][3] != 0 || m[1][3] != 0 || m[2][3] != 0 || m[3][3] != 1) return false;  // projective
  // The rows are the images of the axes: equal lengths, perpendicular (to rounding).
  const Vec3d x{m[0][0], m[0][1], m[0][2]}, y{m[1][0], m[1][1], m[1][2]}, z{m[2][0], m[2][1], m[2][2]};
  const double xx = dot(x, x), yy = dot(y, y), zz = dot(z, z);
  constexpr double kSimilarity = 1e-9;
  const double tolerance = kSimilarity * xx;
  if (!(xx > 0) || std::abs(yy - xx) > tolerance || std::abs(zz - xx) > tolerance || std::abs(dot(x, y)) > tolerance ||
      std::abs(dot(y, z)) > tolerance || std::abs(dot(x, z)) > tolerance)
    return false;
  centre = Vec3d{m[3][0], m[3][1], m[3][2]};
  world_radius = radius * std::sqrt(xx);
  return std::isfinite(world_radius) && std::isfinite(centre.x) && std::isfinite(centre.y) && std::isfinite(centre.z);
}

Vec3f Sphere::normal_at(const Vec3f& p_world) const {
  Vec3d p = world_to_object.transform_point(Vec3d(p_world));
  Vec3d n = normalize(world_to_object.transform_normal_by_inverse(p));
  return Vec3f(flip_normal ? -n : n);
}

Vec2f Sphere::parameters_at(const Vec3f& p_world) const {
  const Vec3d p = world_to_object.transform_point(Vec3d(p_world));
  const double lp = length(p);
  double theta = std::atan2(p.y, p.x);
  if (thetamax > 0 && theta < 0) theta += kTwoPi;
  if (thetamax < 0 && theta > 0) theta -= kTwoPi;
  const double u = thetamax != 0 ? theta / thetamax : 0;
  const double v = v_phi_span != 0 && lp > 0 ? (latitude(p.z * radius / lp, radius) - v_phi0) / v_phi_span : 0;
  return {float(u), float(v)};
}

}  // namespace darc
