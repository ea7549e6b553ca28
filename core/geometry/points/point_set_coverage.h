// Distance-aware intersection of a ray footprint with a point (a disc facing the ray): as for a
// strand (core/geometry/curves/curve_distance_intersector.h), the distance from the ray to the primitive at its
// depth and the footprint there give the fraction of the footprint it covers, and where.
#pragma once

#include <cstddef>

#include "core/footprint/coverage.h"
#include "core/footprint/coverage_mask.h"
#include "core/footprint/distance_ray.h"
#include "core/geometry/points/point_set.h"

namespace darc {

struct PointFragmentHit {
  float t = 0;                    // the centre's depth along the ray
  float coverage = 0;             // fraction of the footprint covered, in (0, 1]
  float distance = 0;             // from the ray to the centre, across the ray
  CoverageMask mask = kFullMask;  // where in the footprint the disc lies (when asked for)
};

// The coverage of a footprint by a disc of radius r whose centre is at (x, y) in the plane
// perpendicular to the ray, the footprint's axes projected there being (ax_x, ax_y) and
// (ay_x, ay_y). Square: the exact area of the disc in the footprint when its axes are
// perpendicular (camera footprints); for sheared ones, and for Box, the square of the disc's
// area aligned with the footprint's axes (the product of two bands, as curves treat a strand
// seen end-on). Either way the coverages of footprints that tile the plane sum to the disc's
// area. Disc: the exact lens of the disc and the footprint's disc of equal area.
float point_coverage(CoverageModel model, float x, float y, float r, float ax_x, float ax_y, float ay_x, float ay_y);

// The fragment of point i for `ray` (prepared by make_distance_ray): false when the centre's
// depth is outside the ray's interval, the radius is 0, or nothing of the footprint is covered.
// Without a footprint (below its min_radius) coverage is the exact hit test.
bool intersect_point_distance(const PointSet& set, size_t i, const DistanceRay& ray, CoverageModel model,
                              PointFragmentHit& hit, bool compute_mask = false);

}  // namespace darc
