// A bounding volume hierarchy over primitive boxes, with the two walks the hiders need: the
// nearest hit of a thin ray (depth-first, near children first), and the footprint walk of a ray
// widened to a cone by its footprint, front to back by a priority queue, so that "every
// primitive nearer than t has been visited" is known at every step (the A-buffer composites what
// is final and the ray stops once it is opaque).
//
// Built as a binary tree (binned SAH, Wald 2007), then collapsed into a 4-wide tree whose nodes
// hold their children's boxes side by side, so that one step tests four boxes at once (SSE on
// x86-64; a portable loop elsewhere that gives bitwise the same result: core/accel/bvh_slab4.h).
//
// Why a BVH and not the seed's uniform grid: hair is dense where it grows and empty around it,
// and grass seen at a grazing angle puts thousands of blades in the near cells; a grid sized for
// the mean density fits neither (docs/performance-640.md measures both).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <span>
#include <vector>

#include "core/math/bbox.h"
#include "core/accel/bvh_slab4.h"
#include "core/math/ray.h"
#include "core/footprint/ray_footprint.h"

namespace darc {

// A 4-wide node: the boxes of up to four children (structure of arrays) and what each child is:
// count 0 and a node index, a leaf of `count` primitives from prims[child], or no child at all
// (its bit clear in `valid`).
struct alignas(16) Bvh4Node {
  Slab4Boxes boxes{};  // empty slots hold zeros (never hit: `valid` masks them)
  uint32_t child[4] = {0, 0, 0, 0};
  uint8_t count[4] = {0, 0, 0, 0};
  uint8_t valid = 0;  // bit k: slot k holds a child
};

// One pending child of a footprint walk: nothing inside it within reach of the ray lies at t
// before t_lo, and the reach there is at most `grow`.
struct BvhQueueEntry {
  float t_lo, grow;
  uint32_t ref;    // node index, or first primitive index of a leaf
  uint32_t count;  // 0: a node; else a leaf of `count` primitives
};

// The per-ray scratch of the walks (one per thread and ray depth; reused, never shared).
struct BvhScratch {
  std::vector<BvhQueueEntry> stack;
  // Pending children of a footprint walk sorted by decreasing t_lo (the nearest at the back): a
  // new entry is inserted by a short scan from the back, because children lie close behind the
  // node just opened (cheaper than a binary heap at the queue lengths seen, 5-40).
  std::vector<BvhQueueEntry> queue;
};

enum class BvhBuildPath { Simd, Portable };

class Bvh {
 public:
  Bvh() = default;

  // Builds over prim_bounds[i] for primitive index i. Empty and non-finite boxes are left out.
  // Deterministic: the same boxes give the same tree for any thread count, and on either path
  // (Simd: box unions with SSE where the machine has it; Portable: plain loops; bitwise the same
  // tree, tested).
  static Bvh build(std::span<const BBox> prim_bounds, BvhBuildPath path = BvhBuildPath::Simd);

  bool empty() const { return nodes_.empty(); }
  std::span<const Bvh4Node> nodes() const { return nodes_; }
  std::span<const uint32_t> primitives() const { return prims_; }
  size_t memory_bytes() const { return nodes_.capacity() * sizeof(Bvh4Node) + prims_.capacity() * sizeof(uint32_t); }

  // Nearest-hit walk: calls test(prim, ray) for candidate primitives, nearer boxes first; a test
  // that hits shortens ray.tmax, which prunes the rest. Returns the number of nodes visited.
  template <class Test>
  uint64_t nearest(Ray& ray, BvhScratch& scratch, Test&& test) const;

  // Footprint walk: the ray widened by footprint.reach(t). Calls visit(prim) once for every
  // primitive whose box comes within reach of the ray, in increasing order of the boxes' nearest
  // depth, and progress(t_final) before each node or leaf is opened: every primitive whose part
  // within reach lies at t < t_final has been visited. progress returning false stops the walk;
  // so does t_final passing ray.tmax (which visit may shorten). Returns the nodes visited.
  template <class Visit, class Progress>
  uint64_t footprint_walk(Ray& ray, const RayFootprint& footprint, BvhScratch& scratch, Visit&& visit,
                          Progress&& progress) const;

 private:
  std::vector<Bvh4Node> nodes_;  // nodes_[0] is the root
  std::vector<uint32_t> prims_;
  BBox bounds_;  // of every primitive in the tree
};

namespace bvh_detail {

// Inserts e into q kept sorted by decreasing t_lo: the back is the nearest entry (equal keys:
// the later entry is taken first; deterministic either way).
inline void queue_insert(std::vector<BvhQueueEntry>& q, const BvhQueueEntry& e) {
  q.push_back(e);
  size_t i = q.size() - 1;
  while (i > 0 && q[i - 1].t_lo < e.t_lo) {
    q[i] = q[i - 1];
    --i;
  }
  q[i] = e;
}

// The largest depth t = dot(p - o, d) / dot(d, d) of a point p of the box.
inline float far_depth(const Ray& r, const BBox& b) {
  float x = std::max((b.lo.x - r.o.x) * r.d.x, (b.hi.x - r.o.x) * r.d.x);
  float y = std::max((b.lo.y - r.o.y) * r.d.y, (b.hi.y - r.o.y) * r.d.y);
  float z = std::max((b.lo.z - r.o.z) * r.d.z, (b.hi.z - r.o.z) * r.d.z);
  return (x + y + z) / dot(r.d, r.d);
}

}  // namespace bvh_detail

template <class Test>
uint64_t Bvh::nearest(Ray& ray, BvhScratch& scratch, Test&& test) const {
  if (nodes_.empty()) return 0;
  const Slab4Ray sr(ray);
  std::vector<BvhQueueEntry>& stack = scratch.stack;
  stack.clear();
  stack.push_back({ray.tmin, 0.0f, 0, 0});
  uint64_t visited = 0;
  while (!stack.empty()) {
    const BvhQueueEntry e = stack.back();
    stack.pop_back();
    if (e.t_lo > ray.tmax) continue;  // a nearer hit was found since it was pushed
    if (e.count > 0) {
      for (uint32_t i = e.ref; i < e.ref + e.count; ++i) test(prims_[i], ray);
      continue;
    }
    const Bvh4Node& node = nodes_[e.ref];
    ++visited;
    Slab4Result hit = slab4(sr, node.boxes, 0.0f, ray.tmin, ray.tmax);
    unsigned mask = hit.mask & node.valid;
    // Push the hit children farthest first, so the nearest is opened next.
    BvhQueueEntry children[4];
    int n = 0;
    for (int k = 0; k < 4; ++k) {
      if (!((mask >> k) & 1)) continue;
      BvhQueueEntry c{hit.t0[k], 0.0f, node.child[k], node.count[k]};
      int i = n++;
      while (i > 0 && children[i - 1].t_lo < c.t_lo) {
        children[i] = children[i - 1];
        --i;
      }
      children[i] = c;
    }
    for (int i = 0; i < n; ++i) stack.push_back(children[i]);
  }
  return visited;
}

template <class Visit, class Progress>
uint64_t Bvh::footprint_walk(Ray& ray, const RayFootprint& footprint, BvhScratch& scratch, Visit&& visit,
                             Progress&& progress) const {
  if (nodes_.empty()) return 0;
  const float dd = dot(ray.d, ray.d);
  if (!(dd > 0.0f) || !std::isfinite(dd)) return 0;
  const Slab4Ray sr(ray);
  const ReachBound reach = footprint.walk_reach_bound();
  // The reach over a child's interval of the ray (nothing before t = 0 is within it).
  auto reach_over = [&](float t0, float t1) { return reach.max_over(std::max(0.0f, t0), std::max(0.0f, t1)); };
  std::vector<BvhQueueEntry>& queue = scratch.queue;
  queue.clear();
  // A child enters the queue when the ray's cone comes within its box. A point p of the box
  // within reach of the ray at t_p puts ray(t_p) inside the box grown by reach(t_p) (a cube
  // around the cone's disc), so t_p lies in the ray's interval [t0, t1] through the grown box:
  // t0 is the child's key. `grow` bounds reach(t_p) for every point of the node; a child takes
  // the smaller of its parent's bound and the largest reach over its own [t0, t1] (found with
  // the parent's grow, so it holds every point of the child within reach; the reach is convex,
  // so its largest is at an end: the far end for a footprint that grows, the near end for one
  // that shrinks toward a light), so a child's grown box lies inside its parent's and keys never
  // decrease along the walk.
  {
    // The root's bound: no point of the tree lies farther along the ray than its largest depth.
    float far = std::min(bvh_detail::far_depth(ray, bounds_), ray.tmax);
    queue.push_back({ray.tmin, reach_over(ray.tmin, far), 0, 0});
  }
  // Children wholly behind the plane the sub-rays start from are never within the footprint
  // (RayFootprint::start_half_space): a shadow ray skips the surface it leaves. A box is behind
  // when its corner farthest along the plane's normal is.
  StartHalfSpace start;
  const bool has_start = footprint.start_half_space(ray.o, ray.d, start);
  auto wholly_behind = [&](const Slab4Boxes& b, int k) {
    const float x = start.n.x > 0 ? b.hi_x[k] : b.lo_x[k];
    const float y = start.n.y > 0 ? b.hi_y[k] : b.lo_y[k];
    const float z = start.n.z > 0 ? b.hi_z[k] : b.lo_z[k];
    return start.excludes(start.at(Vec3f{x, y, z}));
  };
  uint64_t visited = 0;
  while (!queue.empty()) {
    const BvhQueueEntry e = queue.back();
    queue.pop_back();
    if (e.t_lo > ray.tmax || !progress(e.t_lo)) break;
    if (e.count > 0) {
      for (uint32_t i = e.ref; i < e.ref + e.count; ++i) visit(prims_[i]);
      continue;
    }
    const Bvh4Node& node = nodes_[e.ref];
    ++visited;
    Slab4Result hit = slab4(sr, node.boxes, e.grow, ray.tmin, ray.tmax);
    unsigned mask = hit.mask & node.valid;
    for (int k = 0; k < 4; ++k) {
      if (!((mask >> k) & 1)) continue;
      if (has_start && wholly_behind(node.boxes, k)) continue;
      float grow = std::min(e.grow, reach_over(hit.t0[k], hit.t1[k]));
      bvh_detail::queue_insert(queue, {hit.t0[k], grow, node.child[k], node.count[k]});
    }
  }
  return visited;
}

}  // namespace darc
