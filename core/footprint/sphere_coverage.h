// What a whole sphere covers of a footprint, analytically (issue 18 item 1, "quadrics: coverage
// from the distance to the silhouette"): the sub-rays (u, v) that meet a sphere are those whose
// distance to its centre is at most its radius, a quadratic inequality Q(u, v) >= 0 in the
// footprint coordinates, because a sub-ray's direction (pencil) or origin (parallel) is affine
// in (u, v). Its region is an ellipse (the silhouette seen through the footprint); the coverage
// is the exact area of that ellipse within the footprint square Q = [-1/2, 1/2]^2 (an affine map
// makes the ellipse the unit disc and the square a parallelogram), so a sphere far smaller than
// the footprint, which every sub-ray misses, still covers what it should.
//
// Pencil (apex A, sub-ray directions D(u, v)): with a = C - A, a sub-ray meets the sphere where
// (D . a)^2 >= (|a|^2 - r^2) |D|^2 on the nappe the interval lies on. Parallel (origins O(u, v),
// direction d): where |(C - O) x d|^2 <= r^2 |d|^2.
#pragma once

#include "core/footprint/coverage_mask.h"
#include "core/footprint/footprint_frame.h"
#include "core/math/vec.h"

namespace darc {

struct SphereFootprintHit {
  float coverage = 0;     // area of the silhouette within the footprint, in (0, 1]
  CoverageMask mask = 0;  // the mask points inside the silhouette
  // Where the sphere is shaded: the footprint's centre when the silhouette holds it, else the
  // point of the covered region nearest the silhouette's centre.
  float u = 0, v = 0;
  bool covers_centre = false;
  float t_near = 0, t_far = 0;  // the sphere's depth range along the ray (conservative)
};

enum class SphereCoverage {
  Miss,         // nothing of the footprint is covered (or all of it lies outside the interval)
  Covered,      // hit holds the coverage
  NotAnalytic,  // the apex inside the sphere, the sphere across the interval's ends or across
                // the plane of the apex, or a silhouette that is not an ellipse in the
                // footprint: the caller keeps the sub-ray tests
};

SphereCoverage sphere_coverage(const FootprintFrame& frame, const Vec3d& centre, double radius,
                               SphereFootprintHit& hit);

// The area of the unit disc within the convex polygon p[0..n) (counter-clockwise or clockwise),
// exact: the sum over its edges of the disc's signed area in the triangle (0, p_i, p_i+1).
double unit_disc_area_in_polygon(const double (*p)[2], int n);

}  // namespace darc
