// Exact ray / curve-segment intersection (Nakamaru & Ohno 2002, "Ray Tracing for Curves
// Primitive", as structured in pbrt-v4's Curve::IntersectRay), for the flat ribbons of a
// CurveSet: ribbons facing the ray, or oriented by per-end normals.
#pragma once

#include <cstddef>

#include "core/geometry/curves/curve_set.h"
#include "core/math/ray.h"
#include "core/math/vec.h"

namespace darc {

struct CurveHit {
  float t = 0;    // ray parameter: hit point = ray.o + t * ray.d (depth of the curve axis point)
  float u = 0;    // along the segment, in [0, 1]
  float v = 0;    // across the ribbon in [-1, 1]: signed offset / half-width, positive towards cross(d, tangent)
  Vec3f p;        // world-space hit point on the ray
  Vec3f tangent;  // unit dC/du (falls back to the chord, never zero)
  Vec3f normal;   // unit ribbon normal, on the side of the ray origin
};

// The nearest intersection of `ray` with segment `segment` of `set` with t in (ray.tmin, ray.tmax).
// Returns false (leaving `hit` untouched) on a miss, for hidden (width <= 0) parts, and for
// non-finite rays.
bool intersect_segment(const CurveSet& set, size_t segment, const Ray& ray, CurveHit& hit);

// Whether the ribbon of a segment given in a ray's frame (control points `cp`: the ray runs along
// +z through the origin, z is depth; `width`: its Bézier width coefficients; facing the ray)
// covers the point (x, y) of the ray's cross-section: the leaf tests intersect_segment makes, for
// the parallel ray through (x, y). What the distance hider measures a segment against where no
// band describes it (a segment shorter on the screen than it is wide).
bool ribbon_covers_point(const Vec3f cp[4], const float width[4], float x, float y);

}  // namespace darc
