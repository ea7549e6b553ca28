// The classic hider: N x N stratified jittered samples per pixel, each traced with exact
// hit/miss tests; semi-transparent hits are composited front to back by continuing the ray.
// This is the baseline the distance-aware hider is measured against.
#pragma once

#include "core/scene.h"
#include "integrator/film.h"
#include "integrator/ray_scratch.h"
#include "integrator/render_stats.h"
#include "integrator/tracer.h"
#include "shading/scene_shading.h"

namespace darc {

struct HiderContext {
  const Scene& scene;
  const SceneShading& shading;
  const Tracer& tracer;
  uint32_t seed;
  int samples_x, samples_y;
};

// Renders every sample whose filter footprint reaches `tile`'s accumulator.
void render_tile_stochastic(const HiderContext& ctx, const PixelRect& sample_rect, TileAccumulator& acc,
                            RayCounters& counters);

// Radiance and alpha seen along one camera ray (exposed for tests).
struct SampleValue {
  Vec3f color;
  float alpha = 0;
  float depth = 0;  // nearest hit distance (infinity when nothing was hit)
};
SampleValue trace_camera_ray(const HiderContext& ctx, const Ray& ray, RayCounters& counters, RayScratchStack& scratch);

}  // namespace darc
