// The distance hider's secondary rays (SecondaryRayTracer): shadow, reflection and refraction
// rays with footprints, traced through the same footprint walk and A-buffer as camera rays. A
// shadow ray leaves the receiving footprint's patch (or, for a surface seen on part of the
// footprint, the whole patch, its points weighted as they are seen).
#pragma once

#include "integrator/distance_hider.h"
#include "integrator/secondary_rays.h"

namespace darc {

class FootprintSecondaryRays : public SecondaryRayTracer {
 public:
  FootprintSecondaryRays(const DistanceContext& ctx, RayCounters& counters, RayScratchStack& scratch)
      : ctx_(ctx), counters_(counters), scratch_(scratch) {}

  // A surface seen on part of the footprint (ABuffer::surface_at_visible_part): the points it is
  // seen at, and the whole footprint's patch on its plane (centre and axes), whose points are
  // the footprint's.
  struct SeenSurface {
    FootprintPointWeights weights;
    Vec3f centre, dPdx, dPdy;
  };
  // The surface being shaded (null: none, or not seen on part of the footprint).
  void shading(const SeenSurface* seen) { seen_ = seen; }

  Vec3f shadow_transmittance(const Interaction& at, const Vec3f& l, float distance, const RayFootprint* incoming,
                             const PathState& path) override;
  bool cone_shadow_transmittance(const Interaction& at, const Vec3f& l, float distance, float half_angle,
                                 const RayFootprint* incoming, const PathState& path, Vec3f& transmittance) override;
  Vec3f radiance(const Interaction& at, const Ray& ray, const RayFootprint* footprint, const PathState& next,
                 const Vec3f& beyond) override;

 private:
  // A surface seen on part of the footprint is lit where it is seen: the shadow ray leaves the
  // whole footprint's patch and its points are averaged with the weights they are seen with.
  // The seen part's bounding box instead (RayFootprint::part) takes in the points between what
  // is seen: on a scalp seen through hair, the points under the strands, in their shadows.
  Vec3f seen_surface_transmittance(const Interaction& at, const Vec3f& l, float distance, const PathState& path);

  const DistanceContext& ctx_;
  RayCounters& counters_;
  RayScratchStack& scratch_;
  const SeenSurface* seen_ = nullptr;
  float cone_ = 0;  // while a cone shadow ray is traced: its half-angle
};

}  // namespace darc
