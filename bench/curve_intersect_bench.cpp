// Segments tested per second by the exact intersector and by the distance-aware one (with a
// ray footprint of about one pixel), on the same rays: rays that mostly miss (the common case
// behind an acceleration structure's loose bounds) and rays aimed at each segment.
#include <benchmark/benchmark.h>

#include <cmath>
#include <random>

#include "core/geometry/curves/curve_builder.h"
#include "core/geometry/curves/curve_distance_intersector.h"
#include "core/geometry/curves/curve_intersector.h"

namespace darc {
namespace {

constexpr int kStrands = 256;           // curly catmull-rom strands
constexpr int kVerticesPerStrand = 12;  // 9 segments each
constexpr float kStrandWidth = 0.02f;   // thin hair relative to a ~1 unit curl
// Angle between neighbouring camera rays: at the camera's ~20 units this makes a footprint of
// ~0.02, one strand width, i.e. strands about a pixel wide, the case the distance hider is for.
constexpr float kPixelAngle = 0.001f;
constexpr float kMinFootprintRadius = 1e-7f;  // the hider's floor, scene-scale relative

CurveSet make_hair() {
  std::mt19937 rng(7);  // fixed seed: the same scene every run
  std::uniform_real_distribution<float> jitter(-0.3f, 0.3f);
  CurvesInput in;
  in.basis = *standard_basis("catmull-rom");
  in.constantwidth = kStrandWidth;
  for (int s = 0; s < kStrands; ++s) {
    in.nvertices.push_back(kVerticesPerStrand);
    float x0 = jitter(rng) * 10, y0 = jitter(rng) * 10;
    for (int v = 0; v < kVerticesPerStrand; ++v) {
      float a = 1.3f * v + jitter(rng);
      in.P.insert(in.P.end(), {x0 + 0.5f * std::cos(a), y0 + 0.5f * std::sin(a), 0.4f * v + jitter(rng)});
    }
  }
  CurveSet set;
  uint32_t next = 0;
  append_curves(set, in, 0, next);
  return set;
}

// Rays from a camera 20 units away towards random points of each segment's bound.
std::vector<Ray> make_rays(const CurveSet& set, bool aim_at_curve) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  std::vector<Ray> rays;
  for (size_t i = 0; i < set.size(); ++i) {
    Vec3f target;
    if (aim_at_curve) {
      target = bezier_evaluate(set.control_points(i), unit(rng));
    } else {
      BBox b = set.segment_bounds(i);
      target = b.lo + mul(b.extent(), Vec3f{unit(rng), unit(rng), unit(rng)});
    }
    Vec3f origin{0, -20, 2};
    rays.push_back(Ray{origin, normalize(target - origin)});
  }
  return rays;
}

void run(benchmark::State& state, bool aim_at_curve) {
  CurveSet set = make_hair();
  std::vector<Ray> rays = make_rays(set, aim_at_curve);
  size_t hits = 0;
  for (auto _ : state) {
    for (size_t i = 0; i < set.size(); ++i) {
      CurveHit hit;
      hits += intersect_segment(set, i, rays[i], hit) ? 1 : 0;
    }
    benchmark::DoNotOptimize(hits);
  }
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations()) * static_cast<int64_t>(set.size()));
  state.counters["hit_fraction"] = static_cast<double>(hits) / static_cast<double>(state.iterations() * set.size());
}

// A perspective camera ray's footprint: differentials perpendicular to the ray, one pixel apart.
RayFootprint pixel_footprint(const Ray& ray) {
  Vec3f side = normalize(cross(ray.d, Vec3f{0, 0, 1}));
  Vec3f up = cross(side, ray.d);
  RayFootprint f;
  f.ddx = side * kPixelAngle;
  f.ddy = up * kPixelAngle;
  f.min_radius = kMinFootprintRadius;
  return f;
}

void run_distance(benchmark::State& state, bool aim_at_curve) {
  const CoverageModel model = static_cast<CoverageModel>(state.range(0));
  CurveSet set = make_hair();
  std::vector<Ray> rays = make_rays(set, aim_at_curve);
  std::vector<RayFootprint> footprints;
  std::vector<SegmentEnds> ends;
  for (size_t i = 0; i < set.size(); ++i) {
    footprints.push_back(pixel_footprint(rays[i]));
    ends.push_back(segment_ends(set, i));
  }
  size_t hits = 0;
  for (auto _ : state) {
    for (size_t i = 0; i < set.size(); ++i) {
      CurveFragmentHit hit;
      hits += intersect_segment_distance(set, i, rays[i], footprints[i], model, ends[i], hit) ? 1 : 0;
    }
    benchmark::DoNotOptimize(hits);
  }
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations()) * static_cast<int64_t>(set.size()));
  state.counters["hit_fraction"] = static_cast<double>(hits) / static_cast<double>(state.iterations() * set.size());
}

void BM_CurveSegmentInBound(benchmark::State& state) { run(state, false); }
void BM_CurveSegmentAimed(benchmark::State& state) { run(state, true); }
void BM_DistanceSegmentInBound(benchmark::State& state) { run_distance(state, false); }
void BM_DistanceSegmentAimed(benchmark::State& state) { run_distance(state, true); }
BENCHMARK(BM_CurveSegmentInBound);
BENCHMARK(BM_CurveSegmentAimed);
// Argument: the coverage model (0 box = the seed's, 1 disc, 2 square = the hider's default).
BENCHMARK(BM_DistanceSegmentInBound)->Arg(int(CoverageModel::Box))->Arg(int(CoverageModel::Square));
BENCHMARK(BM_DistanceSegmentAimed)->Arg(int(CoverageModel::Box))->Arg(int(CoverageModel::Square));

}  // namespace
}  // namespace darc

BENCHMARK_MAIN();
