// The footprint-aware grid traversal against brute force over random boxes and rays: every box
// within the footprint's reach of the ray is visited, layer_done's t_final promise holds, no
// cell is visited twice in consecutive layers; and the degenerate inputs.
#include "core/accel/footprint_traversal.h"

#include <gtest/gtest.h>

#include "support/random_footprint_scene.h"

#include <algorithm>
#include <map>
#include <random>
#include <vector>

namespace darc {
namespace {

constexpr int kBoxes = 150;
constexpr int kRays = 200;

using test::first_t_within_reach;
std::vector<BBox> random_boxes(std::mt19937& rng) { return test::random_boxes(rng, kBoxes); }
using test::random_ray;

// Which cell a span handed to visit_cell belongs to (non-empty cells have distinct starts).
uint32_t cell_of_span(const UniformGrid& grid, std::span<const uint32_t> prims) {
  auto offset = uint32_t(prims.data() - grid.cell_prims().data());
  auto offsets = grid.cell_offsets();
  return uint32_t(std::upper_bound(offsets.begin(), offsets.end(), offset) - offsets.begin() - 1);
}

struct TraversalRecord {
  std::map<uint32_t, double> promised_before_visit;  // prim -> last t_final announced before its first visit
  std::vector<float> t_finals;
  bool cell_revisited_in_next_layer = false;
};

TraversalRecord record_traversal(const UniformGrid& grid, const Ray& ray, const RayFootprint& fp) {
  TraversalRecord rec;
  std::vector<uint32_t> previous_layer, this_layer;
  double promised = -1e30;
  traverse_with_footprint(
      grid, ray, fp,
      [&](std::span<const uint32_t> prims) {
        uint32_t cell = cell_of_span(grid, prims);
        if (std::find(previous_layer.begin(), previous_layer.end(), cell) != previous_layer.end())
          rec.cell_revisited_in_next_layer = true;
        this_layer.push_back(cell);
        for (uint32_t p : prims) rec.promised_before_visit.emplace(p, promised);
      },
      [&](float t_final) {
        rec.t_finals.push_back(t_final);
        promised = t_final;
        previous_layer.swap(this_layer);
        this_layer.clear();
        return true;
      });
  return rec;
}

TEST(FootprintTraversal, VisitsEveryBoxWithinReachAndKeepsTheTFinalPromise) {
  std::mt19937 rng(7);
  std::vector<BBox> boxes = random_boxes(rng);
  UniformGrid grid = UniformGrid::build(boxes);
  int within_reach = 0;
  for (int r = 0; r < kRays; ++r) {
    Ray ray;
    RayFootprint fp;
    random_ray(rng, ray, fp);
    TraversalRecord rec = record_traversal(grid, ray, fp);
    EXPECT_FALSE(rec.cell_revisited_in_next_layer) << "ray " << r;
    EXPECT_TRUE(std::is_sorted(rec.t_finals.begin(), rec.t_finals.end())) << "ray " << r;
    for (uint32_t b = 0; b < boxes.size(); ++b) {
      double t_first = first_t_within_reach(boxes[b], ray, fp);
      if (t_first < 0) continue;
      ++within_reach;
      auto it = rec.promised_before_visit.find(b);
      ASSERT_NE(it, rec.promised_before_visit.end()) << "ray " << r << " never visited box " << b;
      // Visited after a layer_done(t_final) with t_final >= t_first would break the promise.
      EXPECT_LT(it->second, t_first) << "ray " << r << " box " << b;
    }
  }
  EXPECT_GT(within_reach, kRays);  // the test exercises many boxes
}

TEST(FootprintTraversal, StoppingAtLayerDoneStopsTheWalk) {
  std::vector<BBox> boxes;
  for (int i = 0; i < 20; ++i) boxes.push_back(BBox{Vec3f{float(i), 0, 0}, Vec3f{i + 0.5f, 0.5f, 0.5f}});
  UniformGrid grid = UniformGrid::build(boxes);
  Ray ray{{-1, 0.25f, 0.25f}, {1, 0, 0}};
  int layers = 0;
  traverse_with_footprint(
      grid, ray, RayFootprint{}, [](std::span<const uint32_t>) {}, [&](float) { return ++layers < 3; });
  EXPECT_EQ(layers, 3);
}

TEST(FootprintTraversal, EmptyGridVisitsNothing) {
  UniformGrid grid;
  int calls = 0;
  uint64_t cells = traverse_with_footprint(
      grid, Ray{{0, 0, 0}, {0, 0, 1}}, RayFootprint{}, [&](std::span<const uint32_t>) { ++calls; },
      [&](float) {
        ++calls;
        return true;
      });
  EXPECT_EQ(cells, 0u);
  EXPECT_EQ(calls, 0);
}

TEST(FootprintTraversal, RaysOutsideTheReachVisitNothing) {
  std::mt19937 rng(3);
  UniformGrid grid = UniformGrid::build(random_boxes(rng));
  auto count_prims = [&](const Ray& ray, const RayFootprint& fp) {
    int prims = 0;
    traverse_with_footprint(
        grid, ray, fp, [&](std::span<const uint32_t> p) { prims += int(p.size()); }, [](float) { return true; });
    return prims;
  };
  RayFootprint thin;
  thin.dox = Vec3f{0.01f, 0, 0};
  thin.doy = Vec3f{0, 0.01f, 0};
  // Pointing away from the grid; passing 5 units beside it; a zero and a NaN direction.
  EXPECT_EQ(count_prims(Ray{{-5, 5, 5}, {-1, 0, 0}}, thin), 0);
  EXPECT_EQ(count_prims(Ray{{-5, 5, 17}, {1, 0, 0}}, thin), 0);
  EXPECT_EQ(count_prims(Ray{{5, 5, 5}, {0, 0, 0}}, thin), 0);
  EXPECT_EQ(count_prims(Ray{{5, 5, 5}, {std::nanf(""), 0, 1}}, thin), 0);
  // The same beside-ray with a footprint reaching 8 units (past the boxes' top at z <= 11.2) does find them.
  RayFootprint wide;
  wide.dox = Vec3f{16, 0, 0};
  EXPECT_GT(count_prims(Ray{{-5, 5, 17}, {1, 0, 0}}, wide), 0);
}

}  // namespace
}  // namespace darc
