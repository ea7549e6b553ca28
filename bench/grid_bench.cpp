// Uniform grid: build time for a hair-like scene of 1M thin boxes, and traversal speed
// (rays per second, each ray walking the grid to its end and box-testing every primitive once).
#include <benchmark/benchmark.h>

#include <random>
#include <vector>

#include "core/accel/uniform_grid.h"

namespace darc {
namespace {

constexpr int kSceneSize = 1 << 20;     // boxes, about the curve-segment count of a dense fur scene
constexpr float kSceneExtent = 100.0f;  // the boxes' centres fill a cube of this size
constexpr float kSegmentLength = 1.0f;  // a thin box: a short strand segment...
constexpr float kSegmentWidth = 0.02f;  // ...and its width
constexpr int kRaysPerBatch = 4096;

std::vector<BBox> thin_boxes(int count) {
  std::mt19937 rng(1);
  std::uniform_real_distribution<float> u(0, kSceneExtent), dir(-1, 1);
  std::vector<BBox> boxes;
  boxes.reserve(size_t(count));
  for (int i = 0; i < count; ++i) {
    Vec3f a{u(rng), u(rng), u(rng)};
    Vec3f b = a + normalize(Vec3f{dir(rng), dir(rng), dir(rng)}) * kSegmentLength;
    BBox box;
    box.extend(a);
    box.extend(b);
    boxes.push_back(box.expanded(kSegmentWidth * 0.5f));
  }
  return boxes;
}

const std::vector<BBox>& scene() {
  static const std::vector<BBox> boxes = thin_boxes(kSceneSize);  // built once, read-only afterwards
  return boxes;
}

std::vector<Ray> random_rays(int count) {
  std::mt19937 rng(2);
  std::uniform_real_distribution<float> u(0, kSceneExtent), dir(-1, 1);
  std::vector<Ray> rays;
  for (int i = 0; i < count; ++i) rays.push_back(Ray{{u(rng), u(rng), -10}, normalize(Vec3f{dir(rng), dir(rng), 1})});
  return rays;
}

void BM_GridBuild(benchmark::State& state) {
  const std::vector<BBox>& boxes = scene();
  for (auto _ : state) {
    UniformGrid grid = UniformGrid::build(boxes);
    benchmark::DoNotOptimize(grid.cell_prims().data());
  }
  UniformGrid grid = UniformGrid::build(boxes);
  auto res = grid.resolution();
  state.counters["cells"] = double(grid.cell_count());
  state.counters["refs_per_prim"] = double(grid.cell_prims().size()) / double(boxes.size());
  state.counters["res_x"] = res[0];
  state.SetItemsProcessed(state.iterations() * int64_t(boxes.size()));
}
BENCHMARK(BM_GridBuild)->Unit(benchmark::kMillisecond);

// Full traversal (no early exit) with mailboxed box tests: an upper bound on per-ray grid cost.
void BM_GridTraverse(benchmark::State& state) {
  const std::vector<BBox>& boxes = scene();
  UniformGrid grid = UniformGrid::build(boxes);
  std::vector<Ray> rays = random_rays(kRaysPerBatch);
  Mailbox mailbox(grid.primitive_count());
  int64_t box_tests = 0, cells = 0;
  for (auto _ : state) {
    for (const Ray& ray : rays) {
      mailbox.next_ray();
      grid.traverse(ray, [&](std::span<const uint32_t> prims, float, float) {
        ++cells;
        for (uint32_t p : prims) {
          if (!mailbox.first_visit(p)) continue;
          float t0, t1;
          ++box_tests;
          benchmark::DoNotOptimize(boxes[p].intersect(ray, t0, t1));
        }
        return true;
      });
    }
  }
  state.SetItemsProcessed(state.iterations() * kRaysPerBatch);  // items/s = rays/s
  double ray_count = double(state.iterations()) * kRaysPerBatch;
  state.counters["box_tests_per_ray"] = double(box_tests) / ray_count;
  state.counters["cells_per_ray"] = double(cells) / ray_count;
}
BENCHMARK(BM_GridTraverse)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace darc

BENCHMARK_MAIN();
