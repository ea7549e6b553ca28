// Nearest-hit ray casting against a Scene (curves, spheres, polygons) through its acceleration
// structure's nearest-hit query, with exact hit/miss tests: the visibility query of the stochastic hider.
#pragma once

#include "core/scene/interaction.h"
#include "core/scene/scene.h"
#include "integrator/hit_filter.h"
#include "integrator/render_stats.h"

#include <cstdint>

namespace darc {

class Tracer {
 public:
  explicit Tracer(const Scene& scene);

  // Nearest visible hit with t in (ray.tmin, ray.tmax). Sides 1 primitives seen from behind
  // are not visible; hits `filter` skips are not either (shadow rays also pass primitives whose
  // Transmission is Transparent). Counters are added to `counters`.
  // `scratch` is the query's working memory (one per thread and ray depth).
  bool nearest_hit(const Ray& ray, Interaction& hit, RayCounters& counters, TraversalScratch& scratch,
                   const HitFilter& filter = {}) const;

 private:
  const Scene& scene_;
};

}  // namespace darc
