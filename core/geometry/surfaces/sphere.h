// The RI Sphere quadric: `Sphere radius zmin zmax thetamax`, in object space around the z axis,
// theta measured in the xy plane from +x (degrees in RIB, radians here), placed in the world
// by an object-to-world matrix. Intersection happens in object space in double precision.
#pragma once

#include "core/math/bbox.h"
#include "core/math/matrix.h"
#include "core/math/ray.h"
#include "core/geometry/surfaces/surface_hit.h"

namespace darc {

struct Sphere {
  double radius = 1;  // |radius| from the RIB (the sign only flips the normal)
  double zmin = -1;   // clip range in object z, clamped to [-radius, radius], zmin <= zmax
  double zmax = 1;
  double thetamax = 0;       // signed sweep in radians, |thetamax| <= 2*pi (negative sweeps clockwise)
  double v_phi0 = 0;         // latitude (asin(z/r)) where v = 0: at the RIB's zmin
  double v_phi_span = 0;     // latitude change from v = 0 to v = 1 (negative when the RIB has zmin > zmax)
  bool flip_normal = false;  // parametric normal dP/du x dP/dv points inward
  bool degenerate = true;    // zero radius, zero height, zero sweep or a singular matrix: never hit
  Matrix4 object_to_world;
  Matrix4 world_to_object;

  // Builds the sphere from RIB values (thetamax in degrees). Out-of-range values are clamped,
  // degenerate ones give a sphere that is never hit and has empty bounds. The RI parametric
  // normal dP/du x dP/dv is outward for radius > 0, zmin < zmax, thetamax > 0; each of a
  // negative radius, zmin > zmax and a negative thetamax flips it.
  static Sphere make(double radius, double zmin, double zmax, double thetamax_degrees, const Matrix4& object_to_world);

  // World-space bounds of the clipped object-space box (conservative, rounded outward).
  BBox bounds() const;

  // Nearest hit with t in the open interval (ray.tmin, ray.tmax), or false.
  bool intersect(const Ray& ray, SurfaceHit& hit) const;

  // True for a whole sphere (no clipping in z or theta) placed by a similarity (rotation,
  // uniform scale, translation): it is then the ball of `radius` around `centre` in the world,
  // whose silhouette footprint coverage takes analytically (core/footprint/sphere_coverage.h).
  bool whole_ball(Vec3d& centre, double& world_radius) const;

  // The unit geometric normal (as intersect's hit.ng) at the sphere point nearest the world
  // point p (p need not lie exactly on the sphere).
  Vec3f normal_at(const Vec3f& p_world) const;

  // The surface parameters (u along theta, v along latitude, as intersect gives them) of the
  // surface point nearest p_world, not clamped to the sweep (so that their differences across a
  // footprint are smooth).
  Vec2f parameters_at(const Vec3f& p_world) const;
};

}  // namespace darc
