// The classic hider: N x N stratified jittered samples per pixel, each traced with exact
// hit/miss tests; semi-transparent hits are composited front to back by continuing the ray.
// Shadow, reflection and refraction rays are exact rays too. This is the baseline the
// distance-aware hider is measured against.
#pragma once

#include "core/scene/scene.h"
#include "integrator/film.h"
#include "integrator/hit_filter.h"
#include "integrator/ray_scratch.h"
#include "integrator/render_stats.h"
#include "integrator/secondary_rays.h"
#include "integrator/tracer.h"
#include "shading/scene_shading.h"

namespace darc {

struct HiderContext {
  const Scene& scene;
  const SceneShading& shading;
  const Tracer& tracer;
  uint32_t seed;
  int samples_x, samples_y;
  SecondaryRaySettings secondary{};
};

// The secondary-ray settings of a frame: the threshold, Option "trace" "maxdepth", and an
// offset for ray origins relative to the scene's size.
SecondaryRaySettings make_secondary_settings(const Scene& scene, float contribution_threshold);

// Renders every sample whose filter footprint reaches `tile`'s accumulator.
void render_tile_stochastic(const HiderContext& ctx, const PixelRect& sample_rect, TileAccumulator& acc,
                            RayCounters& counters);

// Radiance and alpha seen along one camera ray (exposed for tests).
struct SampleValue {
  Vec3f color;
  float alpha = 0;
  float depth = 0;  // nearest hit distance (infinity when nothing was hit)
};
// `path`: the ray's place on its path (camera rays: the default); `filter`: what it must not hit
// (the surface or strand a secondary ray leaves).
SampleValue trace_camera_ray(const HiderContext& ctx, const Ray& ray, RayCounters& counters, RayScratchStack& scratch,
                             const PathState& path = {}, const HitFilter& filter = {});

}  // namespace darc
