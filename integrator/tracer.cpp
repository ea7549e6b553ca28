#include "integrator/tracer.h"

#include "core/geometry/curves/curve_intersector.h"

namespace darc {

Tracer::Tracer(const Scene& scene) : scene_(scene) {}

bool Tracer::nearest_hit(const Ray& ray_in, Interaction& out, RayCounters& counters, TraversalScratch& scratch,
                         const HitFilter& filter) const {
  Ray ray = ray_in;
  uint32_t best = kNoPrimitive;
  float best_t = 0, best_u = 0;
  const CurveSet& cs = scene_.curves;
  counters.cells_visited += scene_.accel.nearest(ray, scratch, [&](uint32_t p, Ray&) {
      uint32_t local;
      const Scene::PrimKind kind = scene_.prim_kind(p, local);
      switch (kind) {
        case Scene::PrimKind::CurveSegment: {
          if (cs.strand_id[local] == filter.skip_strand) return;
          const Material& m = scene_.materials[cs.attribute_id[local]];
          if (filter.shadow && m.transmission == Transmission::Transparent) return;
          ++counters.segment_tests;
          CurveHit h;
          if (!intersect_segment(cs, local, ray, h)) return;
          if (cs.oriented(local) && m.hides_back_of(lerp(h.u, cs.end_normal(local, 0), cs.end_normal(local, 1)), ray.d))
            return;
          best = p, best_t = h.t, best_u = h.u;
          ray.tmax = h.t;
          break;
        }
        case Scene::PrimKind::Surface: {
          const Material& m = scene_.materials[scene_.surfaces.material(local)];
          if (filter.shadow && m.transmission == Transmission::Transparent) return;
          ++counters.surface_tests;
          SurfaceHit h;
          Ray r = ray;
          if (p == filter.origin_primitive) r.tmin = std::max(r.tmin, filter.origin_min_t);
          if (!scene_.surfaces.intersect(local, r, h) || m.hides_back_of(h.ng, ray.d)) return;
          best = p, best_t = h.t, best_u = h.u;
          ray.tmax = h.t;
          break;
        }
        case Scene::PrimKind::Point: {
          // A disc facing the ray has no back: Sides does not apply.
          const Material& m = scene_.materials[scene_.points.material[local]];
          if (filter.shadow && m.transmission == Transmission::Transparent) return;
          ++counters.point_tests;
          float t;
          if (!intersect_point(scene_.points, local, ray, t) || filter.skips_primitive(p, t)) return;
          best = p, best_t = t, best_u = 0;
          ray.tmax = t;
          break;
        }
      }
  });
  if (best == kNoPrimitive) return false;
  out = make_interaction(scene_, best, ray_in, best_t, best_u, nullptr);
  return true;
}

}  // namespace darc
