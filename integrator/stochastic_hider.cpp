#include "integrator/stochastic_hider.h"

#include "core/math/concentric_disc.h"
#include "integrator/sample_rng.h"

#include <algorithm>
#include <limits>
#include <utility>
#include <vector>

namespace darc {

namespace {

// Remaining transmittance below which a ray stops collecting semi-transparent layers: the
// rest can change a pixel by at most this fraction.
constexpr float kMinTransmittance = 1e-3f;
// Upper bound on semi-transparent layers per ray (a guard against pathological scenes).
constexpr int kMaxLayers = 256;
// Relative offset that moves a continued ray past the surface it just hit.
constexpr float kContinueEpsilon = 1e-5f;
// The SampleRng streams of a pixel's lens and time permutations: above every sample index (at
// most 64 x 64).
constexpr uint32_t kLensPermutationStream = 0xFFFFFFFFu;
constexpr uint32_t kTimePermutationStream = 0xFFFFFFFEu;
// Secondary rays start this fraction of the scene's size away from their point.
constexpr float kRayOffsetSceneFraction = 1e-6f;
// A sphere a ray leaves is not hit again nearer than this fraction of the scene's size.
constexpr float kSelfOffsetSceneFraction = 1e-4f;

// Exact secondary rays: shadow rays collect the opacity of every hit between the point and the
// light; reflected and refracted rays are camera rays from the point.
class ExactSecondaryRays : public SecondaryRayTracer {
 public:
  ExactSecondaryRays(const HiderContext& ctx, RayCounters& counters, RayScratchStack& scratch)
      : ctx_(ctx), counters_(counters), scratch_(scratch) {}

  Vec3f shadow_transmittance(const Interaction& at, const Vec3f& l, float distance, const RayFootprint*,
                             const PathState& path) override {
    Ray ray{at.P, l, ctx_.secondary.ray_offset, distance};
    ray.time = at.time;
    HitFilter filter = shadow_filter(at);
    Vec3f tr{1, 1, 1};
    TraversalScratch& traversal = scratch_.at(size_t(path.depth) + 1).traversal;
    const float stop = stopping_transmittance(ctx_.secondary, path.weight, kMinTransmittance);
    for (int layer = 0; layer < kMaxLayers; ++layer) {
      Interaction hit;
      if (!ctx_.tracer.nearest_hit(ray, hit, counters_, traversal, filter)) break;
      tr = mul(tr, Vec3f{1, 1, 1} - shadow_opacity(ctx_.scene.materials[hit.material], hit.Os));
      if (max_component(tr) < stop) return max_component(tr) < kMinTransmittance ? Vec3f{} : tr;
      ray.tmin = hit.t + kContinueEpsilon * std::max(1.0f, hit.t);
    }
    return tr;
  }

  Vec3f radiance(const Interaction& at, const Ray& ray, const RayFootprint*, const PathState& next,
                 const Vec3f& beyond) override {
    const SampleValue v =
        trace_camera_ray(ctx_, ray, counters_, scratch_, next, leaving_filter(at, ctx_.scene, ctx_.secondary.self_offset));
    return v.color + beyond * (1 - v.alpha);
  }

 private:
  const HiderContext& ctx_;
  RayCounters& counters_;
  RayScratchStack& scratch_;
};

}  // namespace

SecondaryRaySettings make_secondary_settings(const Scene& scene, float contribution_threshold) {
  SecondaryRaySettings s;
  s.contribution_threshold = contribution_threshold;
  s.max_depth = std::max(0, scene.output.trace_max_depth);
  Vec3f extent = scene.bounds.empty() ? Vec3f{1, 1, 1} : scene.bounds.extent();
  s.ray_offset = kRayOffsetSceneFraction * std::max(max_component(extent), 1e-6f);
  s.self_offset = kSelfOffsetSceneFraction * std::max(max_component(extent), 1e-6f);
  return s;
}

SampleValue trace_camera_ray(const HiderContext& ctx, const Ray& camera_ray, RayCounters& counters,
                             RayScratchStack& scratch, const PathState& path, const HitFilter& filter) {
  SampleValue out;
  out.depth = std::numeric_limits<float>::infinity();
  Vec3f transmittance{1, 1, 1};
  Ray ray = camera_ray;
  ExactSecondaryRays secondary(ctx, counters, scratch);
  TraversalScratch& traversal = scratch.at(size_t(path.depth)).traversal;
  // The filter holds for every layer (a continued ray is still the ray that left the point).
  const HitFilter& layer_filter = filter;
  const float stop = stopping_transmittance(ctx.secondary, path.weight, kMinTransmittance);
  for (int layer = 0; layer < kMaxLayers; ++layer) {
    Interaction hit;
    if (!ctx.tracer.nearest_hit(ray, hit, counters, traversal, layer_filter)) break;
    if (layer == 0) out.depth = hit.t;
    const LazyWeight weight(path.weight * max_component(transmittance));
    ShadedPoint r =
        shade_with_secondary_rays(ctx.shading, ctx.secondary, hit, ray.d, nullptr, path.depth, weight, secondary, counters);
    out.color += mul(transmittance, r.Ci);
    transmittance = mul(transmittance, Vec3f{1, 1, 1} - r.Oi);
    if (max_component(transmittance) < stop) {
      ++counters.rays_terminated_early;
      if (max_component(transmittance) < kMinTransmittance) transmittance = {};
      break;
    }
    ray.tmin = hit.t + kContinueEpsilon * std::max(1.0f, hit.t);
  }
  out.alpha = 1.0f - (transmittance.x + transmittance.y + transmittance.z) / 3.0f;
  return out;
}

namespace {

// The lens (or time) strata of one pixel's samples: sample i takes stratum strata[i], a
// permutation keyed by the pixel and the dimension (Fisher-Yates from its own generator), so that
// lens positions and times are stratified and unrelated to the samples' image positions (what
// correlated strata would turn into a pattern in the blur) and to each other.
void shuffle_strata(uint32_t px, uint32_t py, uint32_t stream, uint32_t seed, std::vector<uint32_t>& strata) {
  for (size_t i = 0; i < strata.size(); ++i) strata[i] = uint32_t(i);
  SampleRng rng(px, py, stream, seed);
  for (size_t i = strata.size(); i > 1; --i) {
    const size_t j = size_t(rng.next_u64() % i);
    std::swap(strata[i - 1], strata[j]);
  }
}

}  // namespace

void render_tile_stochastic(const HiderContext& ctx, const PixelRect& rect, TileAccumulator& acc,
                            RayCounters& counters) {
  const int nx = ctx.samples_x, ny = ctx.samples_y;
  const Camera& camera = ctx.scene.camera;
  RayScratchStack scratch(ctx.scene.accel);
  std::vector<uint32_t> lens_strata(size_t(nx) * size_t(ny)), time_strata(lens_strata.size());
  // Motion blur: each sample sees the scene at one time of the shutter, stratified over the
  // pixel's samples (drawn only when something moves, so that still scenes keep their images).
  const bool moves = ctx.scene.has_motion();
  const ShutterOpening& shutter = ctx.scene.output.shutter_opening;
  for (int py = rect.y0; py < rect.y1; ++py)
    for (int px = rect.x0; px < rect.x1; ++px) {
      if (camera.has_lens()) shuffle_strata(uint32_t(px), uint32_t(py), kLensPermutationStream, ctx.seed, lens_strata);
      if (moves) shuffle_strata(uint32_t(px), uint32_t(py), kTimePermutationStream, ctx.seed, time_strata);
      for (int sy = 0; sy < ny; ++sy)
        for (int sx = 0; sx < nx; ++sx) {
          int index = sy * nx + sx;
          SampleRng rng(uint32_t(px), uint32_t(py), uint32_t(index), ctx.seed);
          float x = px + (sx + rng.next_float()) / nx;
          float y = py + (sy + rng.next_float()) / ny;
          Ray ray;
          if (camera.has_lens()) {
            // The lens stratum this sample takes, jittered, on the disc.
            const uint32_t stratum = lens_strata[size_t(index)];
            const float lu = (float(stratum % uint32_t(nx)) + rng.next_float()) / float(nx);
            const float lv = (float(stratum / uint32_t(nx)) + rng.next_float()) / float(ny);
            const Vec2f lens = concentric_disc(lu, lv);
            ray = camera.generate_lens_ray(x, y, lens.x, lens.y);
          } else {
            ray = camera.generate_ray(x, y);
          }
          // Stratified uniformly, then shaped by how the shutter opens (ShutterOpening::time_at).
          if (moves)
            ray.time = shutter.time_at((float(time_strata[size_t(index)]) + rng.next_float()) / float(nx * ny));
          ++counters.primary_rays;
          SampleValue v = trace_camera_ray(ctx, ray, counters, scratch);
          acc.add_sample(x, y, {v.color.x, v.color.y, v.color.z, v.alpha}, v.depth);
        }
    }
}

}  // namespace darc
