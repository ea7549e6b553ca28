#include "integrator/stochastic_hider.h"

#include "integrator/sample_rng.h"

#include <algorithm>
#include <limits>

namespace darc {

namespace {

// Remaining transmittance below which a ray stops collecting semi-transparent layers: the
// rest can change a pixel by at most this fraction.
constexpr float kMinTransmittance = 1e-3f;
// Upper bound on semi-transparent layers per ray (a guard against pathological scenes).
constexpr int kMaxLayers = 256;
// Relative offset that moves a continued ray past the surface it just hit.
constexpr float kContinueEpsilon = 1e-5f;

}  // namespace

SampleValue trace_camera_ray(const HiderContext& ctx, const Ray& camera_ray, RayCounters& counters,
                             RayScratchStack& scratch) {
  SampleValue out;
  out.depth = std::numeric_limits<float>::infinity();
  Vec3f transmittance{1, 1, 1};
  Ray ray = camera_ray;
  for (int layer = 0; layer < kMaxLayers; ++layer) {
    SurfaceInteraction hit;
    if (!ctx.tracer.nearest_hit(ray, hit, counters, scratch.at(0).traversal)) break;
    if (layer == 0) out.depth = hit.t;
    ShadingPoint sp;
    sp.P = hit.P;
    sp.N = hit.N;
    sp.I = ray.d;
    sp.Cs = hit.Cs;
    sp.Os = hit.Os;
    sp.dPdv = hit.tangent;
    ShadeResult r = ctx.shading.surface(hit.material).shade(sp, ctx.shading.lights(hit.material));
    out.color += mul(transmittance, r.Ci);
    transmittance = mul(transmittance, Vec3f{1, 1, 1} - r.Oi);
    if (max_component(transmittance) < kMinTransmittance) {
      ++counters.rays_terminated_early;
      transmittance = {};
      break;
    }
    ray.tmin = hit.t + kContinueEpsilon * std::max(1.0f, hit.t);
  }
  out.alpha = 1.0f - (transmittance.x + transmittance.y + transmittance.z) / 3.0f;
  return out;
}

void render_tile_stochastic(const HiderContext& ctx, const PixelRect& rect, TileAccumulator& acc,
                            RayCounters& counters) {
  const int nx = ctx.samples_x, ny = ctx.samples_y;
  RayScratchStack scratch(ctx.scene.accel);
  for (int py = rect.y0; py < rect.y1; ++py)
    for (int px = rect.x0; px < rect.x1; ++px)
      for (int sy = 0; sy < ny; ++sy)
        for (int sx = 0; sx < nx; ++sx) {
          int index = sy * nx + sx;
          SampleRng rng(uint32_t(px), uint32_t(py), uint32_t(index), ctx.seed);
          float x = px + (sx + rng.next_float()) / nx;
          float y = py + (sy + rng.next_float()) / ny;
          Ray ray = ctx.scene.camera.generate_ray(x, y);
          ++counters.primary_rays;
          SampleValue v = trace_camera_ray(ctx, ray, counters, scratch);
          acc.add_sample(x, y, {v.color.x, v.color.y, v.color.z, v.alpha}, v.depth);
        }
}

}  // namespace darc
