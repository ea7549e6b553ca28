#include <gtest/gtest.h>

#include <random>
#include <set>
#include <vector>

#include "core/accel/uniform_grid.h"

namespace darc {
namespace {

// Primitives (by index) whose boxes the ray's segment [tmin, tmax] overlaps: the reference.
std::set<uint32_t> brute_force(const std::vector<BBox>& boxes, const Ray& ray) {
  std::set<uint32_t> hit;
  for (uint32_t i = 0; i < boxes.size(); ++i) {
    float t0, t1;
    if (boxes[i].intersect(ray, t0, t1)) hit.insert(i);
  }
  return hit;
}

struct Walked {
  std::set<uint32_t> overlapping;  // reported primitives whose box the ray really overlaps
  std::set<uint32_t> reported;
  int cells = 0;
  bool monotonic = true;
  bool intervals_ordered = true;
};

Walked walk(const UniformGrid& grid, const std::vector<BBox>& boxes, const Ray& ray) {
  Walked w;
  float last_enter = -std::numeric_limits<float>::infinity();
  grid.traverse(ray, [&](std::span<const uint32_t> prims, float t_enter, float t_exit) {
    ++w.cells;
    if (t_enter < last_enter) w.monotonic = false;
    if (t_exit < t_enter) w.intervals_ordered = false;
    last_enter = t_enter;
    for (uint32_t p : prims) {
      w.reported.insert(p);
      float t0, t1;
      if (boxes[p].intersect(ray, t0, t1)) w.overlapping.insert(p);
    }
    return true;
  });
  return w;
}

std::vector<BBox> random_boxes(std::mt19937& rng, int count, Vec3f scale, float max_size) {
  std::uniform_real_distribution<float> u(0, 1);
  std::vector<BBox> boxes;
  for (int i = 0; i < count; ++i) {
    Vec3f c{u(rng) * scale.x, u(rng) * scale.y, u(rng) * scale.z};
    Vec3f h{u(rng) * max_size, u(rng) * max_size, u(rng) * max_size};
    boxes.push_back(BBox{c - h, c + h});
  }
  return boxes;
}

Ray random_ray(std::mt19937& rng, Vec3f scale) {
  std::uniform_real_distribution<float> u(-0.5f, 1.5f);
  std::uniform_real_distribution<float> dir(-1, 1);
  Ray r{{u(rng) * scale.x, u(rng) * scale.y, u(rng) * scale.z}, normalize(Vec3f{dir(rng), dir(rng), dir(rng)})};
  return r;
}

TEST(UniformGrid, RandomBoxesMatchBruteForce) {
  std::mt19937 rng(12345);
  Vec3f scale{10, 6, 3};
  std::vector<BBox> boxes = random_boxes(rng, 4000, scale, 0.3f);
  UniformGrid grid = UniformGrid::build(boxes);
  auto res = grid.resolution();
  EXPECT_GT(res[0] * res[1] * res[2], 1000);  // the heuristic actually subdivides
  EXPECT_GT(res[0], res[2]);                  // proportional to extent
  std::uniform_real_distribution<float> len(0.5f, 20.0f);
  for (int i = 0; i < 400; ++i) {
    Ray ray = random_ray(rng, scale);
    if (i % 3 == 0) ray.tmax = len(rng);  // finite segments, some ending inside the grid
    if (i % 5 == 0) ray.tmin = len(rng) * 0.2f;
    Walked w = walk(grid, boxes, ray);
    ASSERT_EQ(w.overlapping, brute_force(boxes, ray)) << "ray " << i;
    ASSERT_TRUE(w.monotonic);
    ASSERT_TRUE(w.intervals_ordered);
  }
}

TEST(UniformGrid, ReportedCellsLieOnTheRay) {
  // Each reported cell's interval [t_enter, t_exit] must be the ray's passage through that cell:
  // its midpoint lies inside the cell's box.
  std::mt19937 rng(3);
  std::vector<BBox> boxes = random_boxes(rng, 3000, {5, 5, 5}, 0.2f);
  UniformGrid grid = UniformGrid::build(boxes);
  Vec3d cs = grid.cell_size();
  for (int i = 0; i < 200; ++i) {
    Ray ray = random_ray(rng, {5, 5, 5});
    grid.traverse(ray, [&](std::span<const uint32_t> prims, float t0, float t1) {
      Vec3d mid(ray.at(0.5f * (t0 + t1)));
      auto c = grid.cell_of(mid);
      auto expected = grid.cell(grid.cell_index(c[0], c[1], c[2]));
      // The midpoint's cell is the reported one unless the passage is a corner sliver.
      if (t1 - t0 > 1e-3f * float(std::min({cs.x, cs.y, cs.z}))) {
        EXPECT_EQ(expected.data(), prims.data());
      }
      return true;
    });
  }
}

TEST(UniformGrid, EarlyStop) {
  std::mt19937 rng(99);
  std::vector<BBox> boxes = random_boxes(rng, 2000, {4, 4, 4}, 0.2f);
  UniformGrid grid = UniformGrid::build(boxes);
  Ray ray{{-1, 2, 2}, {1, 0, 0}};
  int all = 0;
  grid.traverse(ray, [&](auto, float, float) { return ++all, true; });
  ASSERT_GT(all, 3);
  int calls = 0;
  grid.traverse(ray, [&](auto, float, float) { return ++calls < 3; });
  EXPECT_EQ(calls, 3);
}

TEST(UniformGrid, AxisParallelRays) {
  std::mt19937 rng(5);
  std::vector<BBox> boxes = random_boxes(rng, 3000, {4, 4, 4}, 0.15f);
  UniformGrid grid = UniformGrid::build(boxes);
  std::uniform_real_distribution<float> u(0, 4);
  for (int axis = 0; axis < 3; ++axis)
    for (float sign : {1.0f, -1.0f})
      for (int i = 0; i < 30; ++i) {
        Vec3f o{u(rng), u(rng), u(rng)};
        Vec3f d{0, 0, 0};
        d[axis] = sign;
        o[axis] = i % 2 ? 2.0f : (sign > 0 ? -1.0f : 5.0f);  // from inside, or from outside
        Ray ray{o, d};
        Walked w = walk(grid, boxes, ray);
        ASSERT_EQ(w.overlapping, brute_force(boxes, ray));
        ASSERT_TRUE(w.monotonic);
      }
}

TEST(UniformGrid, FlatScene) {
  // All boxes in the z = 1 plane, zero thickness: the grid is one cell thick and still works
  // for rays across the plane and for rays inside it.
  std::mt19937 rng(8);
  std::uniform_real_distribution<float> u(0, 10), s(0, 0.3f);
  std::vector<BBox> boxes;
  for (int i = 0; i < 2000; ++i) {
    Vec3f c{u(rng), u(rng), 1};
    boxes.push_back(BBox{c - Vec3f{s(rng), s(rng), 0}, c + Vec3f{s(rng), s(rng), 0}});
  }
  UniformGrid grid = UniformGrid::build(boxes);
  EXPECT_EQ(grid.resolution()[2], 1);
  EXPECT_GT(grid.resolution()[0], 10);
  for (int i = 0; i < 200; ++i) {
    Ray across = random_ray(rng, {10, 10, 2});
    Walked w = walk(grid, boxes, across);
    ASSERT_EQ(w.overlapping, brute_force(boxes, across));
    Ray in_plane{{u(rng), u(rng), 1}, normalize(Vec3f{u(rng) - 5, u(rng) - 5, 0})};
    w = walk(grid, boxes, in_plane);
    ASSERT_EQ(w.overlapping, brute_force(boxes, in_plane));
  }
}

TEST(UniformGrid, SinglePrimitive) {
  std::vector<BBox> boxes{BBox{{1, 2, 3}, {2, 3, 4}}};
  UniformGrid grid = UniformGrid::build(boxes);
  EXPECT_EQ(grid.primitive_count(), 1u);
  Walked hit = walk(grid, boxes, Ray{{0, 2.5f, 3.5f}, {1, 0, 0}});
  EXPECT_EQ(hit.overlapping, (std::set<uint32_t>{0}));
  Walked miss = walk(grid, boxes, Ray{{0, 0, 0}, {-1, 0, 0}});
  EXPECT_EQ(miss.cells, 0);
  // A single point primitive (zero extent on every axis).
  std::vector<BBox> point{BBox{{1, 1, 1}, {1, 1, 1}}};
  UniformGrid point_grid = UniformGrid::build(point);
  EXPECT_EQ(walk(point_grid, point, Ray{{0, 1, 1}, {1, 0, 0}}).overlapping, (std::set<uint32_t>{0}));
}

TEST(UniformGrid, EmptyAndInvalidInput) {
  UniformGrid none;
  EXPECT_EQ(walk(none, {}, Ray{{0, 0, 0}, {1, 0, 0}}).cells, 0);
  std::vector<BBox> nothing;
  EXPECT_EQ(walk(UniformGrid::build(nothing), nothing, Ray{{0, 0, 0}, {1, 0, 0}}).cells, 0);
  const float nan = std::numeric_limits<float>::quiet_NaN();
  std::vector<BBox> boxes{BBox{}, BBox{{0, 0, 0}, {1, 1, 1}}, BBox{{nan, 0, 0}, {1, 1, 1}}};
  UniformGrid grid = UniformGrid::build(boxes);
  EXPECT_EQ(grid.primitive_count(), 3u);
  Walked w = walk(grid, boxes, Ray{{-1, 0.5f, 0.5f}, {1, 0, 0}});
  EXPECT_EQ(w.reported, (std::set<uint32_t>{1}));  // the empty and NaN boxes are left out
  // Degenerate rays visit nothing and do not loop.
  EXPECT_EQ(walk(grid, boxes, Ray{{0.5f, 0.5f, 0.5f}, {0, 0, 0}}).cells, 0);
  EXPECT_EQ(walk(grid, boxes, Ray{{0.5f, 0.5f, 0.5f}, {nan, 1, 0}}).cells, 0);
  Ray inverted{{-1, 0.5f, 0.5f}, {1, 0, 0}};
  inverted.tmin = 5;
  inverted.tmax = 1;
  EXPECT_EQ(walk(grid, boxes, inverted).cells, 0);
}

TEST(UniformGrid, CsrLayoutIsConsistent) {
  std::mt19937 rng(21);
  std::vector<BBox> boxes = random_boxes(rng, 1000, {3, 3, 3}, 0.4f);
  UniformGrid grid = UniformGrid::build(boxes);
  auto offsets = grid.cell_offsets();
  ASSERT_EQ(offsets.size(), size_t(grid.cell_count()) + 1);
  EXPECT_EQ(offsets.front(), 0u);
  EXPECT_EQ(offsets.back(), grid.cell_prims().size());
  // Each box is listed in its centre's cell, in increasing primitive order.
  for (uint32_t i = 0; i < boxes.size(); ++i) {
    auto c = grid.cell_of(Vec3d(boxes[i].center()));
    auto prims = grid.cell(grid.cell_index(c[0], c[1], c[2]));
    EXPECT_TRUE(std::binary_search(prims.begin(), prims.end(), i));
  }
}

TEST(Mailbox, OncePerRay) {
  Mailbox mailbox(4);
  mailbox.next_ray();
  EXPECT_TRUE(mailbox.first_visit(2));
  EXPECT_FALSE(mailbox.first_visit(2));
  EXPECT_TRUE(mailbox.first_visit(3));
  mailbox.next_ray();
  EXPECT_TRUE(mailbox.first_visit(2));
}

TEST(Mailbox, DeduplicatesGridReports) {
  // One long box spans many cells; with the mailbox it is tested once.
  std::vector<BBox> boxes{BBox{{0, 0, 0}, {10, 0.1f, 0.1f}}};
  std::mt19937 rng(1);
  for (BBox b : random_boxes(rng, 500, {10, 10, 10}, 0.1f)) boxes.push_back(b);
  UniformGrid grid = UniformGrid::build(boxes);
  Mailbox mailbox(grid.primitive_count());
  mailbox.next_ray();
  int reports = 0, tests = 0;
  grid.traverse(Ray{{-1, 0.05f, 0.05f}, {1, 0, 0}}, [&](std::span<const uint32_t> prims, float, float) {
    for (uint32_t p : prims)
      if (p == 0) {
        ++reports;
        tests += mailbox.first_visit(p);
      }
    return true;
  });
  EXPECT_GT(reports, 1);
  EXPECT_EQ(tests, 1);
}

}  // namespace
}  // namespace darc
