// The one shading path both hiders share: a shader's lobes at an interaction, the light loop
// with shadow rays, the reflected and refracted rays with their footprints, and the pruning of
// every secondary ray by its contribution weight (integrator/contribution.h). What differs per
// hider is how a ray is traced: SecondaryRayTracer.
#pragma once

#include "core/scene/interaction.h"
#include "core/footprint/ray_footprint.h"
#include "integrator/render_stats.h"
#include "shading/scene_shading.h"

#include <algorithm>

namespace darc {

// Where a ray is on its path from the camera.
struct PathState {
  int depth = 0;       // reflection and refraction bounces before this ray (camera rays: 0)
  float weight = 1;    // how much this ray's result can change its sample (1 for camera rays)
};

// A point's weight, computed only when a secondary ray asks for it: the distance hider's weight
// is a sum over the footprint's 64 points, as costly as shading a strand, and most points cast
// no secondary ray at all.
class LazyWeight {
 public:
  explicit LazyWeight(float value) : value_(value), known_(true) {}
  // `compute` must outlive this object.
  template <class Compute>
  explicit LazyWeight(const Compute& compute)
      : compute_([](const void* f) { return (*static_cast<const Compute*>(f))(); }), state_(&compute) {}
  float get() const {
    if (!known_) {
      value_ = compute_(state_);
      known_ = true;
    }
    return value_;
  }

 private:
  float (*compute_)(const void*) = nullptr;
  const void* state_ = nullptr;
  mutable float value_ = 0;
  mutable bool known_ = false;
};

// The widest sun (half-angle, radians: 5 degrees) traced as one cone shadow ray. Within it the
// response's cosine changes by under 0.4 % over the cone and the cone's tangent-plane square of
// directions measures its solid angle to 0.8 %; wider lights are sampled.
inline constexpr float kMaxConeShadowHalfAngle = 5.0f * 3.14159265f / 180.0f;

class SecondaryRayTracer {
 public:
  virtual ~SecondaryRayTracer() = default;
  // The transmittance from `at` toward a light in unit direction l, up to `distance` (infinity
  // for distant lights). `footprint`: the incoming ray's, or null for exact rays. path.weight is
  // the shadow ray's own weight (what its transmittance multiplies).
  virtual Vec3f shadow_transmittance(const Interaction& at, const Vec3f& l, float distance,
                                     const RayFootprint* footprint, const PathState& path) = 0;
  // The mean transmittance toward a light seen as a disc of half-angle `half_angle` around unit
  // direction l, `distance` away (infinity: a sun), in one shadow ray whose footprint grows from
  // the receiving patch to the disc's square; false when this tracer cannot (exact rays, or cone
  // shadows turned off: the light's samples are traced instead).
  virtual bool cone_shadow_transmittance(const Interaction& /*at*/, const Vec3f& /*l*/, float /*distance*/,
                                         float /*half_angle*/, const RayFootprint* /*footprint*/,
                                         const PathState& /*path*/, Vec3f& /*transmittance*/) {
    return false;
  }
  // The colour seen along a reflected or refracted ray from `at` (with its footprint, or null for
  // exact rays); `next` is that ray's path state. `beyond`: the radiance the ray receives if it
  // leaves the scene (a dome's), seen through what the ray's coverage leaves uncovered.
  virtual Vec3f radiance(const Interaction& at, const Ray& ray, const RayFootprint* footprint,
                         const PathState& next, const Vec3f& beyond) = 0;
};

struct SecondaryRaySettings {
  float contribution_threshold = 0;
  int max_depth = 0;
  float ray_offset = 0;  // secondary rays start this far from their point (scene-scale relative)
  // A curved surface a reflected or refracted ray leaves is hit again only beyond this (its far
  // side; the near root is the start point itself, moved by rounding).
  float self_offset = 0;
};

// The transmittance below which a ray of weight `weight` stops: what is behind can change its
// sample by at most weight x transmittance, so with a threshold the ray stops once that is under
// it, and never later than at `floor` (the hider's own limit for camera rays).
inline float stopping_transmittance(const SecondaryRaySettings& s, float weight, float floor) {
  if (!(s.contribution_threshold > 0) || !(weight > 0)) return floor;
  return std::min(1.0f, std::max(floor, s.contribution_threshold / weight));
}

struct ShadedPoint {
  Vec3f Ci;  // premultiplied by Oi
  Vec3f Oi;
};

// Shades `at`, seen along `incoming` (unit direction) with footprint `footprint` (null: exact
// ray) by a ray `depth` bounces from the camera whose result at this point can change its sample
// by `weight` (coverage x transmittance in front x the path's weight), lit by its lights with
// shadows, and with its reflected and refracted rays traced by `tracer`, each secondary ray
// pruned when weight x its own factor is below the threshold:
// a pruned shadow ray counts the light as unoccluded, a pruned reflected or refracted ray as
// black (what a ray that leaves the scene sees).
ShadedPoint shade_with_secondary_rays(const SceneShading& shading, const SecondaryRaySettings& settings,
                                      const Interaction& at, const Vec3f& incoming, const RayFootprint* footprint,
                                      int depth, const LazyWeight& weight, SecondaryRayTracer& tracer,
                                      RayCounters& counters);

}  // namespace darc
