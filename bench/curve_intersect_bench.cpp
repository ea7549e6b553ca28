// Segments tested per second by the exact intersector, for rays that mostly miss (the common
// case behind an acceleration structure's loose bounds) and for rays aimed at each segment.
#include <benchmark/benchmark.h>

#include <cmath>
#include <random>

#include "core/curve_builder.h"
#include "core/curve_intersector.h"

namespace darc {
namespace {

constexpr int kStrands = 256;           // curly catmull-rom strands
constexpr int kVerticesPerStrand = 12;  // 9 segments each
constexpr float kStrandWidth = 0.02f;   // thin hair relative to a ~1 unit curl

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

void BM_CurveSegmentInBound(benchmark::State& state) { run(state, false); }
void BM_CurveSegmentAimed(benchmark::State& state) { run(state, true); }
BENCHMARK(BM_CurveSegmentInBound);
BENCHMARK(BM_CurveSegmentAimed);

}  // namespace
}  // namespace darc

BENCHMARK_MAIN();
