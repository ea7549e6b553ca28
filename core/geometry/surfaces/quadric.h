// The RI quadrics other than the sphere (RI Spec 3.2, section 5.3): Cone, Cylinder, Disk,
// Paraboloid, Hyperboloid and Torus, each swept around the object z axis by theta in
// [0, thetamax] (degrees in RIB, radians here) and placed in the world by an object-to-world
// matrix. Intersection happens in object space in double precision, like the Sphere's.
//
// The spec's parametrization, with theta = u * thetamax (and phi = phimin + v (phimax - phimin)
// for the torus), in object space:
//   Cone height radius:         (radius (1-v) cos theta, radius (1-v) sin theta, v height)
//   Cylinder radius zmin zmax:  (radius cos theta, radius sin theta, zmin + v (zmax - zmin))
//   Disk height radius:         (radius (1-v) cos theta, radius (1-v) sin theta, height)
//   Paraboloid rmax zmin zmax:  (r cos theta, r sin theta, z), z = zmin + v (zmax - zmin),
//                               r = rmax sqrt(z / zmax)
//   Hyperboloid point1 point2:  the segment (1-v) point1 + v point2 rotated by theta about z
//   Torus major minor phimin phimax: ((major + minor cos phi) cos theta,
//                                     (major + minor cos phi) sin theta, minor sin phi)
// The geometric normal is the parametric normal dP/du x dP/dv (never flipped toward the ray;
// Orientation and Sides act on it later). Its sign follows from the signs of the arguments: a
// negative thetamax, a reversed z range (Cylinder, Paraboloid), a negative Cone height or a
// reversed phi range (Torus) flip it. A negative radius does not: it only moves the points half a
// turn round the axis (or, for the torus's minor radius, round the tube).
#pragma once

#include "core/math/bbox.h"
#include "core/math/matrix.h"
#include "core/math/ray.h"
#include "core/geometry/surfaces/surface_hit.h"

namespace darc {

enum class QuadricKind { Cone, Cylinder, Disk, Paraboloid, Hyperboloid, Torus };

struct Quadric {
  QuadricKind kind = QuadricKind::Disk;
  // The RIB arguments in object units, signs kept (the parametrization uses them). Which fields
  // a kind uses: Cone (height, radius), Cylinder (radius, zmin, zmax), Disk (height, radius),
  // Paraboloid (radius = rmax, zmin, zmax), Hyperboloid (point1, point2), Torus (major_radius,
  // radius = minor radius, phimin, phimax).
  double radius = 0;
  double height = 0;
  double zmin = 0, zmax = 0;
  Vec3d point1, point2;
  double major_radius = 0;
  double phimin = 0, phimax = 0;  // radians
  double thetamax = 0;            // signed sweep in radians, |thetamax| <= 2 pi

  // Derived when made. The surfaces of revolution with a z range (Cone, Cylinder, Paraboloid and
  // a non-flat Hyperboloid) are x^2 + y^2 = rho2_a w^2 + rho2_b w + rho2_c, where
  // w = (z - w_origin) / w_scale is the axial parameter in which rho^2 is a simple quadratic.
  double rho2_a = 0, rho2_b = 0, rho2_c = 0;
  double w_origin = 0, w_scale = 1;
  double z_lo = 0, z_hi = 0;  // object z range of the surface, z_lo <= z_hi
  bool flat = false;          // a plane z = z_lo: the Disk, and a Hyperboloid whose points share z
  bool degenerate = true;     // zero area, zero sweep, non-finite input or a singular matrix
  Matrix4 object_to_world;
  Matrix4 world_to_object;

  // Builders from RIB values (angles in degrees). Out-of-range sweeps are clamped to 360 degrees;
  // degenerate input gives a quadric that is never hit and has empty bounds. A Cone of height 0
  // is the Disk it describes (same points, same normal).
  static Quadric cone(double height, double radius, double thetamax_degrees, const Matrix4& object_to_world);
  static Quadric cylinder(double radius, double zmin, double zmax, double thetamax_degrees,
                          const Matrix4& object_to_world);
  static Quadric disk(double height, double radius, double thetamax_degrees, const Matrix4& object_to_world);
  static Quadric paraboloid(double rmax, double zmin, double zmax, double thetamax_degrees,
                            const Matrix4& object_to_world);
  static Quadric hyperboloid(const Vec3d& point1, const Vec3d& point2, double thetamax_degrees,
                             const Matrix4& object_to_world);
  static Quadric torus(double major_radius, double minor_radius, double phimin_degrees, double phimax_degrees,
                       double thetamax_degrees, const Matrix4& object_to_world);

  // World-space bounds of the object-space box of the full revolution (conservative, rounded
  // outward).
  BBox bounds() const;

  // Nearest hit with t in the open interval (ray.tmin, ray.tmax), or false.
  bool intersect(const Ray& ray, SurfaceHit& hit) const;

  // The unit geometric normal (as intersect's hit.ng) at the surface point nearest the world
  // point p (p need not lie exactly on the surface).
  Vec3f normal_at(const Vec3f& p_world) const;

  // Where an object-space point lies on the surface: its (u, v) and the parametric normal
  // dP/du x dP/dv there (object space, not normalized). Returns false when `clip` is set and the
  // point is outside the swept, clipped part.
  struct SurfacePoint {
    double u = 0, v = 0;
    Vec3d normal;
  };
  bool locate(const Vec3d& p_object, bool clip, SurfacePoint& out) const;
  // The surface parameters (as intersect gives them) of the surface point nearest p_world.
  Vec2f parameters_at(const Vec3f& p_world) const;

 private:
  void finish(const Matrix4& object_to_world_in, bool nondegenerate_shape);
  // Ray parameters (object space, ascending) where the ray meets the untrimmed implicit surface.
  int implicit_roots(const Vec3d& o, const Vec3d& d, double roots[4]) const;
  int torus_roots(const Vec3d& o, const Vec3d& d, double roots[4]) const;
  bool locate_torus(const Vec3d& p, bool clip, SurfacePoint& out) const;
};

}  // namespace darc
