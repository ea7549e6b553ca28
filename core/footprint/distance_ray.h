// A ray prepared once for the footprint queries of many primitives (curve segments, points):
// a frame perpendicular to its direction and its footprint's reach.
#pragma once

#include "core/footprint/ray_footprint.h"
#include "core/math/ray.h"
#include "core/math/vec.h"

namespace darc {

// A ray prepared once for the many segments (or points) it is tested against: a float frame
// perpendicular to its direction and its footprint's reach. Per segment, only the control points are moved
// into the frame (then turned in the frame's plane to lie along their chord), which is what
// makes a rejected segment cost a few dozen flops.
struct DistanceRay {
  bool valid = false;      // false for non-finite or zero directions: every test misses
  Vec3f origin, dir;       // dir is unit
  Vec3f frame_x, frame_y;  // with dir, a right-handed orthonormal frame (frame_y = dir x frame_x)
  float ray_length = 1;    // |ray.d|: t = depth / ray_length
  float t_min = 0, t_max = 0;
  float time = 0;               // Ray::time
  bool sweeps_shutter = false;  // Ray::sweeps_shutter, over [sweep_from, sweep_to]
  float sweep_from = 0, sweep_to = 1;
  ReachBound reach;        // the footprint's reach at ray parameter t (RayFootprint::reach_bound)
  const RayFootprint* footprint = nullptr;
  // A footprint whose sub-rays start on a plane and all leave it to one side (a shadow ray's
  // receiving patch, RayFootprint::start_half_space). The patch leans along the ray (a strand's
  // band runs along the strand), so its sub-rays start at different depths: a neighbour beside
  // it can sit at depth <= t_min on the centre ray and still be met by the sub-rays from the
  // patch's near side (the curve intersector's StartCut). `start` is relative to the origin.
  bool has_start = false;
  StartHalfSpace start;
  // The least depth (t * ray_length) of a point ahead of the sub-rays: t_min's, or with a start
  // half-space the lowest of the sub-rays' origins.
  float depth_min = 0;
};

DistanceRay make_distance_ray(const Ray& ray, const RayFootprint& footprint);

}  // namespace darc
