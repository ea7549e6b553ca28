#include "bench/embree_render.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <optional>

#include "integrator/pixel_filter.h"
#include "integrator/render_frame.h"
#include "integrator/sample_rng.h"
#include "shading/scene_shading.h"

namespace darc::bench {

namespace {

// The same constants as integrator/stochastic_hider.cpp, so that both composite alike.
// Remaining transmittance below which a ray stops collecting semi-transparent layers.
constexpr float kMinTransmittance = 1e-3f;
// Upper bound on intersections per camera ray (a guard against pathological scenes).
constexpr int kMaxLayers = 256;
// Relative offset that moves a continued ray past the surface it just hit.
constexpr float kContinueEpsilon = 1e-5f;

template <typename T>
T bezier(const T* c, float u) {
  float s = 1 - u;
  return c[0] * (s * s * s) + c[1] * (3 * s * s * u) + c[2] * (3 * s * u * u) + c[3] * (u * u * u);
}

// Unit dC/du of a cubic Bézier, else its chord (coincident control points), else any direction
// perpendicular to the ray: the same fallbacks as core/geometry/curves/curve_intersector.cpp.
Vec3f curve_tangent(const Vec3f* cp, float u, const Vec3f& dir) {
  float s = 1 - u;
  Vec3f d = (cp[1] - cp[0]) * (3 * s * s) + (cp[2] - cp[1]) * (6 * s * u) + (cp[3] - cp[2]) * (3 * u * u);
  Vec3f t = normalize(d);
  if (length_squared(t) == 0.0f) t = normalize(cp[3] - cp[0]);
  if (length_squared(t) == 0.0f) {
    Vec3f unused;
    orthonormal_basis(dir, t, unused);
  }
  return t;
}

struct RenderContext {
  const EmbreeScene& embree;
  const Scene& scene;
  const SceneShading& shading;
};

// The ShadingPoint and material of an Embree hit, built as integrator/tracer.cpp builds them
// from darc's own hits; nullopt when darc would not see it (one-sided, seen from behind).
std::optional<std::pair<ShadingPoint, uint32_t>> shading_point(const RenderContext& ctx, const RTCRayHit& rh,
                                                               const Ray& ray) {
  const EmbreeGeometry& g = ctx.embree.geometry(rh.hit.geomID);
  const uint32_t i = g.source[rh.hit.primID];
  const float t = rh.ray.tfar;
  ShadingPoint sp;
  sp.P = ray.o + ray.d * t;
  sp.I = ray.d;
  uint32_t material = 0;
  switch (g.kind) {
    case EmbreeGeometry::Kind::FlatCurves:
    case EmbreeGeometry::Kind::OrientedCurves: {
      const CurveSet& cs = ctx.scene.curves;
      const float u = std::clamp(rh.hit.u, 0.0f, 1.0f);
      material = cs.attribute_id[i];
      const Material& m = ctx.scene.materials[material];
      Vec3f n = -ray.d;  // ribbons facing the ray: the normal faces the viewer
      if (cs.oriented(i)) {
        n = normalize(lerp(u, cs.end_normal(i, 0), cs.end_normal(i, 1)));
        if (m.flip_normals) n = -n;
        if (m.sides == 1 && dot(n, ray.d) > 0) return std::nullopt;
      }
      sp.N = n;
      sp.Cs = bezier(cs.colors(i), u);
      sp.Os = bezier(cs.opacities(i), u);
      sp.dPdv = curve_tangent(cs.control_points(i), u, ray.d);
      break;
    }
    case EmbreeGeometry::Kind::PolygonTriangles:
    case EmbreeGeometry::Kind::Surfaces: {
      // The surface index in Scene::surfaces; convex polygons come as triangles of polygon i.
      const SurfaceSet& surfaces = ctx.scene.surfaces;
      const uint32_t surface =
          g.kind == EmbreeGeometry::Kind::PolygonTriangles ? uint32_t(surfaces.spheres.size()) + i : i;
      material = surfaces.material(surface);
      const Material& m = ctx.scene.materials[material];
      // darc's own normals, as core/scene/interaction.cpp builds them (not the triangle's winding).
      const Vec3f ng = surfaces.geometric_normal(surface, sp.P);
      if (m.hides_back_of(ng, ray.d)) return std::nullopt;
      const Vec3f ns = surfaces.shading_normal(surface, sp.P);
      sp.N = m.flip_normals ? -ns : ns;
      sp.Cs = m.color;
      sp.Os = m.opacity;
      break;
    }
  }
  return std::make_pair(sp, material);
}

struct SampleRadiance {
  Vec3f color;
  float alpha = 0;
  float depth = std::numeric_limits<float>::infinity();
};

SampleRadiance trace(const RenderContext& ctx, const Ray& camera_ray, EmbreeRenderStats& stats) {
  SampleRadiance out;
  Vec3f transmittance{1, 1, 1};
  RTCIntersectContext ictx;
  rtcInitIntersectContext(&ictx);
  ictx.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;  // neighbouring camera rays of one tile
  float tmin = camera_ray.tmin;
  bool first_visible = true;
  for (int layer = 0; layer < kMaxLayers; ++layer) {
    RTCRayHit rh;
    rh.ray.org_x = camera_ray.o.x, rh.ray.org_y = camera_ray.o.y, rh.ray.org_z = camera_ray.o.z;
    rh.ray.dir_x = camera_ray.d.x, rh.ray.dir_y = camera_ray.d.y, rh.ray.dir_z = camera_ray.d.z;
    rh.ray.tnear = tmin;
    rh.ray.tfar = camera_ray.tmax;
    rh.ray.time = 0;
    rh.ray.mask = std::numeric_limits<unsigned>::max();
    rh.ray.id = 0;
    rh.ray.flags = 0;
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(ctx.embree.handle(), &ictx, &rh);
    ++stats.intersect_calls;
    if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) break;
    const float t = rh.ray.tfar;
    // The origin stays at the camera (Embree's curve self-intersection avoidance is relative to
    // it); only tnear moves past the hit, by the stochastic hider's relative epsilon.
    tmin = t + kContinueEpsilon * std::max(1.0f, t);
    auto point = shading_point(ctx, rh, camera_ray);
    if (!point) continue;
    if (first_visible) out.depth = t, first_visible = false;
    ++stats.shaded_hits;
    ShadeResult r = shade_unshadowed(ctx.shading.surface(point->second), point->first, ctx.shading.lights(point->second));
    out.color += mul(transmittance, r.Ci);
    transmittance = mul(transmittance, Vec3f{1, 1, 1} - r.Oi);
    if (max_component(transmittance) < kMinTransmittance) {
      transmittance = {};
      break;
    }
  }
  out.alpha = 1.0f - (transmittance.x + transmittance.y + transmittance.z) / 3.0f;
  return out;
}

void render_tile(const RenderContext& ctx, int n, uint32_t seed, const PixelRect& rect, TileAccumulator& acc,
                 EmbreeRenderStats& stats) {
  for (int py = rect.y0; py < rect.y1; ++py)
    for (int px = rect.x0; px < rect.x1; ++px)
      for (int sy = 0; sy < n; ++sy)
        for (int sx = 0; sx < n; ++sx) {
          // Exactly integrator/stochastic_hider.cpp's sample positions.
          SampleRng rng(uint32_t(px), uint32_t(py), uint32_t(sy * n + sx), seed);
          float x = px + (sx + rng.next_float()) / n;
          float y = py + (sy + rng.next_float()) / n;
          Ray ray = ctx.scene.camera.generate_ray(x, y);
          ++stats.primary_rays;
          SampleRadiance v = trace(ctx, ray, stats);
          acc.add_sample(x, y, {v.color.x, v.color.y, v.color.z, v.alpha}, v.depth);
        }
}

}  // namespace

Image render_embree(const EmbreeScene& embree, const EmbreeRenderOptions& options, Diagnostics& diag,
                    EmbreeRenderStats& stats) {
  auto start = std::chrono::steady_clock::now();
  const Scene& scene = embree.source();
  const OutputSettings& out = scene.output;
  std::optional<PixelFilter> filter =
      make_pixel_filter(out.filter_name, float(out.filter_width[0]), float(out.filter_width[1]));
  if (!filter) filter = make_pixel_filter("gaussian", 2, 2);  // as render_frame
  Film film(out.xres, out.yres, crop_pixels(out), *filter);
  SceneShading shading(scene, diag);
  RenderContext ctx{embree, scene, shading};
  const int n = std::max(1, options.samples_per_axis);

  std::vector<PixelRect> tiles = film.tiles();
  std::vector<std::optional<TileAccumulator>> accumulators(tiles.size());
  std::vector<EmbreeRenderStats> tile_stats(tiles.size());
  int threads = options.threads > 0 ? options.threads : tbb::this_task_arena::max_concurrency();
  tbb::task_arena arena(threads);
  arena.execute([&] {
    tbb::parallel_for(tbb::blocked_range<size_t>(0, tiles.size(), 1), [&](const tbb::blocked_range<size_t>& r) {
      for (size_t i = r.begin(); i != r.end(); ++i) {
        accumulators[i].emplace(film.make_accumulator(tiles[i]));
        render_tile(ctx, n, options.seed, tiles[i], *accumulators[i], tile_stats[i]);
      }
    });
  });
  for (size_t i = 0; i < tiles.size(); ++i) {  // tile order: the same sums for any thread count
    film.merge(*accumulators[i]);
    stats.primary_rays += tile_stats[i].primary_rays;
    stats.intersect_calls += tile_stats[i].intersect_calls;
    stats.shaded_hits += tile_stats[i].shaded_hits;
  }
  Image image = film.resolve(float(out.exposure_gain), float(out.exposure_gamma));
  stats.render_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return image;
}

}  // namespace darc::bench
