// The Embree peer's renderer: the classic stochastic method as it is done well with Embree 3.
// N x N stratified jittered samples per pixel at exactly the positions darc's stochastic hider
// uses (SampleRng of pixel, sample and seed), one rtcIntersect1 per visible layer, every hit
// shaded with darc's own SceneShading (as integrator/stochastic_hider.cpp's trace_camera_ray),
// semi-transparent layers composited front to back by continuing the ray just past the hit,
// tiles in parallel (oneTBB) merged in tile order into darc's Film: deterministic for any
// thread count. With the same seed it traces the same rays as darc's stochastic hider, so the
// two images differ only where the geometry code differs.
#pragma once

#include <cstdint>

#include "bench/embree_scene.h"
#include "integrator/film.h"
#include "parser/diagnostics.h"

namespace darc::bench {

struct EmbreeRenderOptions {
  int samples_per_axis = 1;  // N of N x N
  int threads = 0;           // 0: all cores
  uint32_t seed = 0;
};

struct EmbreeRenderStats {
  double render_seconds = 0;     // everything after the BVH build: shaders, tiles, film
  uint64_t primary_rays = 0;
  uint64_t intersect_calls = 0;  // rtcIntersect1 calls (primary rays + continuations)
  uint64_t shaded_hits = 0;
};

// Renders the EmbreeScene's source Scene with its own filter, resolution and exposure.
Image render_embree(const EmbreeScene& scene, const EmbreeRenderOptions& options, Diagnostics& diag,
                    EmbreeRenderStats& stats);

}  // namespace darc::bench
