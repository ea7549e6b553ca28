#include "integrator/tracer.h"

#include "core/curve_intersector.h"

namespace darc {

namespace {

template <typename T>
T bezier(const T* c, float u) {
  float s = 1 - u;
  return c[0] * (s * s * s) + c[1] * (3 * s * s * u) + c[2] * (3 * s * u * u) + c[3] * (u * u * u);
}

}  // namespace

Tracer::Tracer(const Scene& scene) : scene_(scene) {}

bool Tracer::nearest_hit(const Ray& ray_in, SurfaceInteraction& out, RayCounters& counters,
                         TraversalScratch& scratch) const {
  Ray ray = ray_in;
  bool found = false;
  const CurveSet& cs = scene_.curves;
  counters.cells_visited += scene_.accel.nearest(ray, scratch, [&](uint32_t p, Ray&) {
      uint32_t local;
      const Scene::PrimKind kind = scene_.prim_kind(p, local);
      switch (kind) {
        case Scene::PrimKind::CurveSegment: {
          ++counters.segment_tests;
          CurveHit h;
          if (!intersect_segment(cs, local, ray, h)) return;
          const Material& m = scene_.materials[cs.attribute_id[local]];
          Vec3f n = -ray.d;
          if (cs.oriented(local)) {
            n = normalize(lerp(h.u, cs.end_normal(local, 0), cs.end_normal(local, 1)));
            if (m.flip_normals) n = -n;
            if (m.sides == 1 && dot(n, ray.d) > 0) return;
          }
          out.t = h.t;
          out.P = h.p;
          out.N = n;
          out.Cs = bezier(cs.colors(local), h.u);
          out.Os = bezier(cs.opacities(local), h.u);
          out.material = cs.attribute_id[local];
          out.primitive = p;
          out.is_curve = true;
          out.u = h.u;
          out.v = h.v;
          out.tangent = h.tangent;
          ray.tmax = h.t;
          found = true;
          break;
        }
        case Scene::PrimKind::Sphere:
        case Scene::PrimKind::Polygon: {
          ++counters.surface_tests;
          SurfaceHit h;
          bool is_sphere = kind == Scene::PrimKind::Sphere;
          bool hit = is_sphere ? scene_.spheres[local].intersect(ray, h) : scene_.polygons[local].intersect(ray, h);
          if (!hit) return;
          uint32_t mi = is_sphere ? scene_.sphere_material[local] : scene_.polygon_material[local];
          const Material& m = scene_.materials[mi];
          Vec3f n = m.flip_normals ? -h.ng : h.ng;
          if (m.sides == 1 && dot(n, ray.d) > 0) return;
          out.t = h.t;
          out.P = h.p;
          out.N = n;
          out.Cs = m.color;
          out.Os = m.opacity;
          out.material = mi;
          out.primitive = p;
          out.is_curve = false;
          out.tangent = {};
          out.u = h.u;
          out.v = h.v;
          ray.tmax = h.t;
          found = true;
          break;
        }
      }
  });
  return found;
}

}  // namespace darc
