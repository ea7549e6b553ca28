// The BVH against brute force over random boxes and rays: the footprint walk visits every box
// within the footprint's reach of the ray, each once, and keeps its t_final promise; the nearest
// walk finds the nearest box hit; the tree covers every valid box once; degenerate inputs.
#include "core/accel/bvh.h"

#include <gtest/gtest.h>

#include "support/random_footprint_scene.h"

#include <algorithm>
#include <bit>
#include <map>
#include <random>
#include <vector>

namespace darc {
namespace {

constexpr int kBoxes = 400;
constexpr int kRays = 300;

using test::first_t_within_reach;
std::vector<BBox> random_boxes(std::mt19937& rng) { return test::random_boxes(rng, kBoxes); }
using test::random_ray;

TEST(Bvh, EveryValidBoxIsInExactlyOneLeaf) {
  std::mt19937 rng(1);
  std::vector<BBox> boxes = random_boxes(rng);
  boxes[7] = BBox{};                                                  // empty: left out
  boxes[9] = BBox{{0, 0, 0}, {std::numeric_limits<float>::infinity(), 1, 1}};  // non-finite: left out
  Bvh bvh = Bvh::build(boxes);
  std::vector<int> seen(boxes.size(), 0);
  for (const Bvh4Node& n : bvh.nodes()) {
    for (int k = 0; k < 4; ++k) {
      if (!((n.valid >> k) & 1) || n.count[k] == 0) continue;
      for (uint32_t i = n.child[k]; i < n.child[k] + n.count[k]; ++i) {
        uint32_t p = bvh.primitives()[i];
        ++seen[p];
        // The leaf's box holds its primitives' boxes.
        EXPECT_LE(n.boxes.lo_x[k], boxes[p].lo.x);
        EXPECT_GE(n.boxes.hi_z[k], boxes[p].hi.z);
      }
    }
  }
  for (size_t p = 0; p < boxes.size(); ++p) EXPECT_EQ(seen[p], (p == 7 || p == 9) ? 0 : 1) << p;
}

TEST(Bvh, FootprintWalkVisitsEveryBoxWithinReachOnceAndKeepsTheTFinalPromise) {
  std::mt19937 rng(2);
  std::vector<BBox> boxes = random_boxes(rng);
  Bvh bvh = Bvh::build(boxes);
  BvhScratch scratch;
  int within_reach = 0;
  for (int r = 0; r < kRays; ++r) {
    Ray ray;
    RayFootprint fp;
    random_ray(rng, ray, fp);
    std::map<uint32_t, int> visits;
    std::map<uint32_t, float> promised_before;  // the last t_final announced before the first visit
    float last_t_final = -std::numeric_limits<float>::infinity();
    bool monotone = true;
    bvh.footprint_walk(
        ray, fp, scratch,
        [&](uint32_t p) {
          if (visits[p]++ == 0) promised_before[p] = last_t_final;
        },
        [&](float t_final) {
          monotone = monotone && t_final >= last_t_final;
          last_t_final = t_final;
          return true;
        });
    EXPECT_TRUE(monotone) << "ray " << r;
    for (uint32_t b = 0; b < boxes.size(); ++b) {
      double t_first = first_t_within_reach(boxes[b], ray, fp);
      if (visits.count(b)) {
        EXPECT_EQ(visits[b], 1) << "ray " << r << " box " << b;
      }
      if (t_first < 0) continue;
      ++within_reach;
      ASSERT_TRUE(visits.count(b)) << "ray " << r << " box " << b << " within reach at t=" << t_first;
      // Promised final before its visit would be a broken promise.
      EXPECT_LE(promised_before[b], t_first) << "ray " << r << " box " << b;
    }
  }
  EXPECT_GT(within_reach, kRays);  // the test exercises many boxes
}

TEST(Bvh, StoppingAtProgressStopsTheWalk) {
  std::vector<BBox> boxes;
  for (int i = 0; i < 64; ++i) boxes.push_back(BBox{Vec3f{float(i), 0, 0}, Vec3f{i + 0.5f, 0.5f, 0.5f}});
  Bvh bvh = Bvh::build(boxes);
  BvhScratch scratch;
  Ray ray{{-1, 0.25f, 0.25f}, {1, 0, 0}};
  int steps = 0, visited = 0;
  bvh.footprint_walk(
      ray, RayFootprint{}, scratch, [&](uint32_t) { ++visited; }, [&](float) { return ++steps < 3; });
  EXPECT_EQ(steps, 3);
  EXPECT_LT(visited, 64);
}

TEST(Bvh, NearestWalkFindsTheNearestBoxHit) {
  std::mt19937 rng(4);
  std::vector<BBox> boxes = random_boxes(rng);
  Bvh bvh = Bvh::build(boxes);
  BvhScratch scratch;
  for (int r = 0; r < kRays; ++r) {
    Ray ray;
    RayFootprint unused;
    random_ray(rng, ray, unused);
    float brute = std::numeric_limits<float>::infinity();
    for (const BBox& b : boxes) {
      float t0, t1;
      if (b.intersect(ray, t0, t1)) brute = std::min(brute, t0);
    }
    Ray walk = ray;
    float found = std::numeric_limits<float>::infinity();
    bvh.nearest(walk, scratch, [&](uint32_t p, Ray& rr) {
      float t0, t1;
      if (boxes[p].intersect(rr, t0, t1) && t0 < found) {
        found = t0;
        rr.tmax = t0;  // a hit shortens the ray, as a primitive test does
      }
    });
    EXPECT_EQ(found, brute) << "ray " << r;
  }
}

TEST(Bvh, EmptyAndDegenerateInputsVisitNothing) {
  Bvh empty = Bvh::build({});
  BvhScratch scratch;
  int calls = 0;
  Ray ray{{0, 0, 0}, {0, 0, 1}};
  EXPECT_EQ(empty.footprint_walk(
                ray, RayFootprint{}, scratch, [&](uint32_t) { ++calls; }, [](float) { return true; }),
            0u);
  std::mt19937 rng(3);
  Bvh bvh = Bvh::build(random_boxes(rng));
  for (Vec3f d : {Vec3f{0, 0, 0}, Vec3f{std::nanf(""), 0, 1}, Vec3f{-1, 0, 0}}) {
    Ray r{{-5, 5, 5}, d};
    bvh.footprint_walk(
        r, RayFootprint{}, scratch, [&](uint32_t) { ++calls; }, [](float) { return true; });
  }
  EXPECT_EQ(calls, 0);
}

// Enough boxes to take the parallel path (subtrees over the parallel threshold).
std::vector<BBox> many_random_boxes(uint32_t seed) {
  std::mt19937 rng(seed);
  std::vector<BBox> boxes;
  for (int k = 0; k < 60; ++k) {
    std::vector<BBox> more = random_boxes(rng);
    boxes.insert(boxes.end(), more.begin(), more.end());
  }
  return boxes;
}

// Two trees are the same to the bit: nodes (children, counts, boxes with their signs of zero)
// and the primitives' order.
void expect_same_tree(const Bvh& a, const Bvh& b) {
  ASSERT_EQ(a.nodes().size(), b.nodes().size());
  ASSERT_EQ(a.primitives().size(), b.primitives().size());
  EXPECT_TRUE(std::equal(a.primitives().begin(), a.primitives().end(), b.primitives().begin()));
  auto bits = [](const Slab4Boxes& x) {
    std::array<uint32_t, 24> out{};
    const float* f = x.lo_x;
    for (size_t i = 0; i < out.size(); ++i) out[i] = std::bit_cast<uint32_t>(f[i]);
    return out;
  };
  for (size_t i = 0; i < a.nodes().size(); ++i) {
    for (int k = 0; k < 4; ++k) {
      EXPECT_EQ(a.nodes()[i].child[k], b.nodes()[i].child[k]);
      EXPECT_EQ(a.nodes()[i].count[k], b.nodes()[i].count[k]);
    }
    EXPECT_EQ(bits(a.nodes()[i].boxes), bits(b.nodes()[i].boxes)) << "node " << i;
  }
}

TEST(Bvh, BuildIsAPureFunctionOfTheBoxes) {
  const std::vector<BBox> boxes = many_random_boxes(5);
  expect_same_tree(Bvh::build(boxes), Bvh::build(boxes));
}

// The build's SIMD box unions (SSE on x86-64) make bitwise the tree of its portable loops: on
// random boxes, on boxes whose corners are signed zeros (min and max must pick the zero the
// portable std::min and std::max pick), and on coincident centroids.
TEST(Bvh, SimdBuildIsBitwiseThePortableOne) {
  std::vector<BBox> boxes = many_random_boxes(6);
  for (int i = 0; i < 3000; ++i) {
    const float z = (i % 2 == 0) ? 0.0f : -0.0f;
    const float a = float(i % 7) * 0.25f;
    boxes.push_back(BBox{{z, -a, z}, {a, (i % 3 == 0) ? -0.0f : 0.0f, a}});
  }
  for (int i = 0; i < 500; ++i) boxes.push_back(BBox{{-1, -1, -1}, {1, 1, 1}});
  expect_same_tree(Bvh::build(boxes, BvhBuildPath::Simd), Bvh::build(boxes, BvhBuildPath::Portable));
}

// The SIMD slab test gives bitwise the results of the portable one, on random boxes and rays,
// including zero direction components (infinite inverses), rays starting on box planes (0 * inf)
// and NaN bounds: golden images must not depend on which path the CPU takes.
TEST(Bvh, SimdSlabTestIsBitwiseThePortableOne) {
#ifndef DARC_SLAB4_SSE
  GTEST_SKIP() << "no SIMD path on this architecture: the portable one is the only one";
#else
  std::mt19937 rng(6);
  std::uniform_real_distribution<float> pos(-5.0f, 5.0f), size(0.0f, 3.0f), grow(0.0f, 0.2f);
  std::uniform_int_distribution<int> special(0, 9);
  int hits = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    Slab4Boxes b;
    for (int k = 0; k < 4; ++k) {
      b.lo_x[k] = pos(rng), b.lo_y[k] = pos(rng), b.lo_z[k] = pos(rng);
      b.hi_x[k] = b.lo_x[k] + size(rng), b.hi_y[k] = b.lo_y[k] + size(rng), b.hi_z[k] = b.lo_z[k] + size(rng);
    }
    Ray ray{{pos(rng), pos(rng), pos(rng)}, normalize(Vec3f{pos(rng), pos(rng), pos(rng)})};
    switch (special(rng)) {
      case 0: ray.d.x = 0.0f; break;                 // parallel to the x slabs
      case 1: ray.d = {0, 0, 1}; ray.o.x = b.lo_x[0]; break;  // on a slab plane: 0 * inf
      case 2: b.lo_y[1] = std::nanf(""); break;      // a NaN bound
      case 3: ray.d.y = -0.0f; break;
      default: break;
    }
    Slab4Ray sr(ray);
    float g = grow(rng), tmin = 0.0f, tmax = trial % 3 == 0 ? std::numeric_limits<float>::infinity() : 8.0f;
    Slab4Result p = slab4_portable(sr, b, g, tmin, tmax), s = slab4_sse(sr, b, g, tmin, tmax);
    ASSERT_EQ(p.mask, s.mask) << "trial " << trial;
    for (int k = 0; k < 4; ++k) {
      ASSERT_EQ(std::bit_cast<uint32_t>(p.t0[k]), std::bit_cast<uint32_t>(s.t0[k])) << "trial " << trial << " box " << k;
      ASSERT_EQ(std::bit_cast<uint32_t>(p.t1[k]), std::bit_cast<uint32_t>(s.t1[k])) << "trial " << trial << " box " << k;
    }
    hits += std::popcount(p.mask);
  }
  EXPECT_GT(hits, 1000);  // the boxes are hit often enough to test the intervals, not only misses
#endif
}

}  // namespace
}  // namespace darc
