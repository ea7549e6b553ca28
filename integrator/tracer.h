// Nearest-hit ray casting against a Scene (curves, spheres, polygons) through its acceleration
// structure's nearest-hit query, with exact hit/miss tests: the visibility query of the stochastic hider.
#pragma once

#include "core/scene.h"
#include "integrator/render_stats.h"

#include <cstdint>

namespace darc {

// What the shader needs to know about a hit.
struct SurfaceInteraction {
  float t = 0;
  Vec3f P;
  Vec3f N;  // shading normal: as the surface defines it, orientation applied (not face-forwarded)
  Vec3f Cs, Os;
  uint32_t material = 0;
  uint32_t primitive = 0;  // grid primitive index
  bool is_curve = false;
  float u = 0, v = 0;
  Vec3f tangent;  // unit, along the curve (zero on surfaces)
};

class Tracer {
 public:
  explicit Tracer(const Scene& scene);

  // Nearest visible hit with t in (ray.tmin, ray.tmax). Sides 1 primitives seen from behind
  // are not visible. Counters are added to `counters`.
  // `scratch` is the query's working memory (one per thread and ray depth).
  bool nearest_hit(const Ray& ray, SurfaceInteraction& hit, RayCounters& counters, TraversalScratch& scratch) const;

 private:
  const Scene& scene_;
};

}  // namespace darc
