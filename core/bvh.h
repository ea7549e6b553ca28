// A bounding volume hierarchy over primitive boxes (binary, binned SAH, Wald 2007), with the
// two walks the hiders need: the nearest hit of a thin ray (depth-first, near child first), and
// the footprint walk of a ray widened to a cone by its footprint, front to back by a priority
// queue, so that "every primitive nearer than t has been visited" is known at every step (the
// A-buffer composites what is final and the ray stops once it is opaque).
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

#include "core/bbox.h"
#include "core/ray.h"
#include "core/ray_footprint.h"

namespace darc {

// 32 bytes: a box and either two children (the first right after the node, the second at
// `offset`) or a range of `count` primitive indices from `offset`.
struct BvhNode {
  BBox box;
  uint32_t offset = 0;
  uint16_t count = 0;  // 0: interior node
  uint8_t axis = 0;    // interior: the split axis (the first child holds the lower centroids)
  uint8_t unused = 0;
};
static_assert(sizeof(BvhNode) == 32);

// One pending node of a footprint walk: nothing inside it within reach of the ray lies at t
// before t_lo, and the reach there is at most `grow`.
struct BvhQueueEntry {
  float t_lo, grow;
  uint32_t node;
};

// The per-ray scratch of the walks (one per thread and ray depth; reused, never shared).
struct BvhScratch {
  std::vector<uint32_t> stack;
  // Pending nodes of a footprint walk sorted by decreasing t_lo (the nearest at the back): a new
  // entry is inserted by a short scan from the back, because children lie close behind the node
  // just opened (cheaper than a binary heap at the queue lengths seen, 5-40).
  std::vector<BvhQueueEntry> queue;
};

class Bvh {
 public:
  Bvh() = default;

  // Builds over prim_bounds[i] for primitive index i. Empty and non-finite boxes are left out.
  // Deterministic: the same boxes give the same tree for any thread count.
  static Bvh build(std::span<const BBox> prim_bounds);

  bool empty() const { return nodes_.empty(); }
  std::span<const BvhNode> nodes() const { return nodes_; }
  std::span<const uint32_t> primitives() const { return prims_; }
  BBox bounds() const { return nodes_.empty() ? BBox{} : nodes_[0].box; }
  size_t memory_bytes() const { return nodes_.capacity() * sizeof(BvhNode) + prims_.capacity() * sizeof(uint32_t); }

  // Nearest-hit walk: calls test(prim, ray) for candidate primitives, nearer boxes first; a test
  // that hits shortens ray.tmax, which prunes the rest. Returns the number of nodes visited.
  template <class Test>
  uint64_t nearest(Ray& ray, BvhScratch& scratch, Test&& test) const;

  // Footprint walk: the ray widened by footprint.reach(t). Calls visit(prim) once for every
  // primitive whose box comes within reach of the ray, in increasing order of the boxes' nearest
  // depth, and progress(t_final) before each node is opened: every primitive whose part within
  // reach lies at t < t_final has been visited. progress returning false stops the walk; so does
  // t_final passing ray.tmax (which visit may shorten). Returns the number of nodes visited.
  template <class Visit, class Progress>
  uint64_t footprint_walk(Ray& ray, const RayFootprint& footprint, BvhScratch& scratch, Visit&& visit,
                          Progress&& progress) const;

 private:
  std::vector<BvhNode> nodes_;
  std::vector<uint32_t> prims_;
};

namespace bvh_detail {

// The ray's inverse direction for slab tests; components of d equal to zero give infinities,
// and the slab test below is written so that 0 * inf (NaN) never rejects.
struct SlabRay {
  float ox, oy, oz, ix, iy, iz;
  explicit SlabRay(const Ray& r)
      : ox(r.o.x), oy(r.o.y), oz(r.o.z), ix(1.0f / r.d.x), iy(1.0f / r.d.y), iz(1.0f / r.d.z) {}
};

// The ray's interval [t0, t1] inside box grown by `grow`, clipped to [tmin, tmax].
inline bool slab(const SlabRay& r, const BBox& b, float grow, float tmin, float tmax, float& t0, float& t1) {
  t1 = tmax;
  t0 = tmin;
  auto axis = [&](float lo, float hi, float o, float inv) {
    float a = (lo - grow - o) * inv, c = (hi + grow - o) * inv;
    float n = std::min(a, c), f = std::max(a, c);
    t0 = n > t0 ? n : t0;  // NaN-safe: a NaN leaves the bound as it is
    t1 = f < t1 ? f : t1;
  };
  axis(b.lo.x, b.hi.x, r.ox, r.ix);
  axis(b.lo.y, b.hi.y, r.oy, r.iy);
  axis(b.lo.z, b.hi.z, r.oz, r.iz);
  return t0 <= t1;
}

// The range of t = dot(p - o, d) / dot(d, d) over the box: where the box lies along the ray.
inline void depth_range(const Ray& r, float inv_dd, const BBox& b, float& lo, float& hi) {
  float px = (b.lo.x - r.o.x) * r.d.x, qx = (b.hi.x - r.o.x) * r.d.x;
  float py = (b.lo.y - r.o.y) * r.d.y, qy = (b.hi.y - r.o.y) * r.d.y;
  float pz = (b.lo.z - r.o.z) * r.d.z, qz = (b.hi.z - r.o.z) * r.d.z;
  lo = (std::min(px, qx) + std::min(py, qy) + std::min(pz, qz)) * inv_dd;
  hi = (std::max(px, qx) + std::max(py, qy) + std::max(pz, qz)) * inv_dd;
}

// Inserts e into q kept sorted by decreasing (t_lo, node): the back is the nearest entry.
inline void queue_insert(std::vector<BvhQueueEntry>& q, BvhQueueEntry e) {
  q.push_back(e);
  size_t i = q.size() - 1;
  while (i > 0 && (q[i - 1].t_lo < e.t_lo || (q[i - 1].t_lo == e.t_lo && q[i - 1].node < e.node))) {
    q[i] = q[i - 1];
    --i;
  }
  q[i] = e;
}

}  // namespace bvh_detail

template <class Test>
uint64_t Bvh::nearest(Ray& ray, BvhScratch& scratch, Test&& test) const {
  if (nodes_.empty()) return 0;
  const bvh_detail::SlabRay sr(ray);
  std::vector<uint32_t>& stack = scratch.stack;
  stack.clear();
  uint64_t visited = 0;
  float t0, t1;
  if (!bvh_detail::slab(sr, nodes_[0].box, 0.0f, ray.tmin, ray.tmax, t0, t1)) return 0;
  stack.push_back(0);
  while (!stack.empty()) {
    const uint32_t index = stack.back();
    stack.pop_back();
    const BvhNode& node = nodes_[index];
    ++visited;
    if (node.count > 0) {
      for (uint32_t i = node.offset; i < node.offset + node.count; ++i) test(prims_[i], ray);
      continue;
    }
    const uint32_t a = index + 1, b = node.offset;
    float ta, tb;
    bool ha = bvh_detail::slab(sr, nodes_[a].box, 0.0f, ray.tmin, ray.tmax, ta, t1);
    bool hb = bvh_detail::slab(sr, nodes_[b].box, 0.0f, ray.tmin, ray.tmax, tb, t1);
    if (ha && hb) {
      // The farther child waits; the nearer is opened next (ties: the first child first).
      if (tb < ta) {
        stack.push_back(a);
        stack.push_back(b);
      } else {
        stack.push_back(b);
        stack.push_back(a);
      }
    } else if (ha) {
      stack.push_back(a);
    } else if (hb) {
      stack.push_back(b);
    }
  }
  return visited;
}

template <class Visit, class Progress>
uint64_t Bvh::footprint_walk(Ray& ray, const RayFootprint& footprint, BvhScratch& scratch, Visit&& visit,
                             Progress&& progress) const {
  if (nodes_.empty()) return 0;
  const float dd = dot(ray.d, ray.d);
  if (!(dd > 0.0f) || !std::isfinite(dd)) return 0;
  const float inv_dd = 1.0f / dd;
  const bvh_detail::SlabRay sr(ray);
  const float reach0 = footprint.reach(0.0f), reach1 = footprint.reach(1.0f) - reach0;
  std::vector<BvhQueueEntry>& queue = scratch.queue;
  queue.clear();
  // Enters node `index` in the queue when the ray's cone comes within its box. A point p of the
  // box within reach of the ray at t_p puts ray(t_p) inside the box grown by reach(t_p) (a cube
  // around the cone's disc), so t_p lies in the ray's interval [t0, t1] through the grown box:
  // t0 is the node's key. `grow` bounds reach(t_p) for every point of the box; a child inherits
  // the smaller of its parent's bound and the reach at the parent's t1, so a child's grown box
  // lies inside its parent's and keys never decrease along the walk.
  auto offer = [&](uint32_t index, float grow) {
    float t0, t1;
    if (!bvh_detail::slab(sr, nodes_[index].box, grow, ray.tmin, ray.tmax, t0, t1)) return;
    bvh_detail::queue_insert(queue, {t0, std::min(grow, reach0 + reach1 * std::max(0.0f, t1)), index});
  };
  {
    // The root: no point of it lies farther along the ray than its box's largest depth.
    float lo, hi;
    bvh_detail::depth_range(ray, inv_dd, nodes_[0].box, lo, hi);
    offer(0, reach0 + reach1 * std::max(0.0f, std::min(hi, ray.tmax)));
  }
  uint64_t visited = 0;
  while (!queue.empty()) {
    const BvhQueueEntry entry = queue.back();
    queue.pop_back();
    if (entry.t_lo > ray.tmax || !progress(entry.t_lo)) break;
    const BvhNode& node = nodes_[entry.node];
    ++visited;
    if (node.count > 0) {
      for (uint32_t i = node.offset; i < node.offset + node.count; ++i) visit(prims_[i]);
    } else {
      offer(entry.node + 1, entry.grow);
      offer(node.offset, entry.grow);
    }
  }
  return visited;
}

}  // namespace darc
