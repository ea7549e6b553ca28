// What a convex planar polygon (a triangle, a mesh face) covers of a footprint, analytically
// (footprint-everything.md §2.2-2.3): its edges become half-planes in footprint coordinates
// (u, v), and so do the ray's depth limits; the footprint square clipped by them is the covered
// region, whose exact area is the coverage under the box filter. The 8x8 mask holds the mask
// points inside every half-plane, decided at the frame's shared sub-rays with a tie rule, so that
// the pieces of a mesh that share an edge own each point on it exactly once.
//
// Pencil footprints (perspective camera rays, shadow rays toward a point light): the edge from
// corner i to j is the plane through the apex A and both corners, E_ij(u, v) = (a_i x a_j) .
// D(u, v) with a = X - A. A sub-ray meets the polygon, on the ray's side of the apex, exactly
// where sigma * side * E_ij >= 0 for every edge (sigma: the polygon's winding seen from A), so
// corners behind the apex need no clipping. Parallel footprints (orthographic rays, shadow rays
// toward a distant light): the edge's plane along d, E_ij = ((X_j - X_i) x d) . (O(u, v) - B).
#pragma once

#include "core/footprint/coverage_mask.h"
#include "core/footprint/footprint_frame.h"
#include "core/math/vec.h"

#include <span>

namespace darc {

// The most corners a polygon may have here (convex faces beyond it keep the sub-ray tests).
inline constexpr int kMaxPolygonCorners = 16;

struct PolygonFootprintHit {
  float coverage = 0;          // area of the covered region, in (0, 1]
  CoverageMask mask = 0;       // the mask points inside
  float t = 0;                 // depth (ray parameter) at (u, v)
  float t_near = 0, t_far = 0;  // the covered region's depth range
  // Where the polygon is shaded: the footprint's centre when the polygon covers it (so that a
  // mesh is shaded at the pixel's centre whichever piece holds it: no jitter from piece to
  // piece), else the covered region's centroid.
  float u = 0, v = 0;
  bool covers_centre = false;
  // The direction in which the ray's sub-rays travel through the polygon (for Sides).
  Vec3f travel;
};

// The coverage of the convex polygon with `corners` (in order around it, planar, at least 3)
// within the frame's ray interval. False when it covers nothing of the footprint (edge-on,
// outside the footprint, or outside the interval).
bool polygon_coverage(const FootprintFrame& frame, std::span<const Vec3f> corners, PolygonFootprintHit& hit);

// A half-plane c + cu u + cv v >= 0 of footprint coordinates.
struct FootprintHalfPlane {
  double c, cu, cv;
};

// The area of the footprint square [-1/2, 1/2]^2 inside every one of the half-planes (at most
// kMaxPolygonCorners + 2 of them).
double footprint_area_within(std::span<const FootprintHalfPlane> half_planes);

}  // namespace darc
