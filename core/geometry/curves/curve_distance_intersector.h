// Distance-aware ray / curve-segment intersection (Nakamaru, Matsuoka & Fujita 2012): the
// Nakamaru–Ohno subdivision, but sub-curves are culled with half-width + the ray footprint
// instead of the half-width alone, and the leaf returns the distance from the ray to the strand
// axis, turned into the fraction of the footprint the strand covers.
#pragma once

#include <cstddef>

#include "core/footprint/coverage.h"
#include "core/footprint/coverage_mask.h"
#include "core/geometry/curves/curve_set.h"
#include "core/math/ray.h"
#include "core/footprint/distance_ray.h"
#include "core/footprint/ray_footprint.h"

namespace darc {

struct CurveFragmentHit {
  float t = 0;         // depth of the strand's closest approach to the ray
  float coverage = 0;  // fraction of the footprint covered, in (0, 1]
  float u = 0;         // along the segment
  float distance = 0;  // from the ray to the strand axis, across the ray
  CoverageMask mask = kFullMask;  // where in the footprint the strand lies (when asked for)
  // A moving strand seen by a ray sweeping the shutter: the shutter time at which it is shaded
  // (when it passes the footprint's centre); -1: the ray's time.
  float time = -1;
};

// Which ends of a segment are ends of its strand: strand ends get a coverage fall-off along the
// strand (the footprint is only partly on the strand side of the end), joints do not.
struct SegmentEnds {
  bool strand_start = false;
  bool strand_end = false;
  // Also cut at the segment's joints where the strand runs straight through them (the leaf's
  // direction within ~30 degrees of the joint's): the A-buffer then adds the pieces of a strand
  // up, so a strand shorter than the footprint covers only its length. Where the strand turns at
  // a joint, the neighbouring pieces overlap instead and count once through their masks.
  bool cut_joints = false;
};


bool intersect_segment_distance(const CurveSet& set, size_t segment, const DistanceRay& ray, CoverageModel model,
                                SegmentEnds ends, CurveFragmentHit& hit, bool compute_mask = false);

// The best (largest coverage, then nearest) closest approach of `ray` to segment `segment` with
// t in (ray.tmin, ray.tmax) and coverage above zero. Returns false when nothing of the footprint
// is covered, for hidden (width <= 0) parts, and for non-finite rays.
bool intersect_segment_distance(const CurveSet& set, size_t segment, const Ray& ray, const RayFootprint& footprint,
                                CoverageModel model, SegmentEnds ends, CurveFragmentHit& hit,
                                bool compute_mask = false);

// The strand ends of segment i of `set` (from strand ids and segment indices).
SegmentEnds segment_ends(const CurveSet& set, size_t i);

}  // namespace darc
