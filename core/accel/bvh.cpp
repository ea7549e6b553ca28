#include "core/accel/bvh.h"

#include <tbb/parallel_invoke.h>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include <array>
#include <bit>
#include <limits>

namespace darc {

namespace {

// A node of the binary tree the build makes before collapsing it: a box and either two children
// (the first right after the node, the second at `offset`) or `count` primitives from `offset`.
struct BvhNode {
  BBox box;
  uint32_t offset = 0;
  uint16_t count = 0;  // 0: interior node
  uint8_t axis = 0;
  uint8_t unused = 0;
};

// Bins per axis of the SAH sweep (Wald 2007 uses 16; more change the tree little).
constexpr int kBins = 16;
// Largest leaf. Curve tests cost far more than box tests, so leaves stay small; the SAH stops
// splitting earlier only where a split gains nothing.
constexpr uint32_t kMaxLeafSize = 4;
// SAH costs: a box test relative to a primitive test. Measured on the benchmark scenes
// (callgrind, 2026-12-01): 1.0 and 0.5 give the same instruction counts within 1 % at 65 bytes
// of tree per segment; 2.0 halves the tree but costs the stochastic hider 25 % more on grass.
constexpr float kTraversalCost = 1.0f;
constexpr float kPrimitiveCost = 1.0f;
// Subtrees with more primitives than this are built in parallel (their two children as tasks).
constexpr uint32_t kParallelThreshold = 8192;

bool valid_box(const BBox& b) {
  for (int a = 0; a < 3; ++a)
    if (!std::isfinite(b.lo[a]) || !std::isfinite(b.hi[a]) || b.lo[a] > b.hi[a]) return false;
  return true;
}

float half_area(const BBox& b) {
  if (b.empty()) return 0.0f;
  Vec3f e = b.extent();
  return e.x * e.y + e.y * e.z + e.z * e.x;
}

// The boxes of a range of primitives: the union of their boxes, and the box of their centroids.
struct RangeBounds {
  BBox box, cbox;
};

// Boxes as four-lane rows (x, y, z and a lane the bounds ignore), so that a union is one
// vector min and one max where the compiler vectorises (SSE2 is x86-64's baseline: no flag);
// min and max are exact, so any lane order or width gives the same bounds.
struct alignas(16) Lanes {
  std::array<float, 4> v;
};

#if defined(__SSE2__)
constexpr bool kHaveSimd = true;
#else
constexpr bool kHaveSimd = false;
#endif

// std::min and std::max per lane; kSimd: with SSE where the machine has it (x86-64's baseline),
// the operands put so that the instructions return what std::min(a, b) = (b < a ? b : a) and
// std::max(a, b) = (a < b ? b : a) return, signed zeros included: the same boxes to the bit on
// both paths (tests/core/accel/bvh_test.cpp builds with both).
template <bool kSimd>
Lanes lane_min(const Lanes& a, const Lanes& b) {
  Lanes r;
#if defined(__SSE2__)
  if constexpr (kSimd) {
    _mm_store_ps(r.v.data(), _mm_min_ps(_mm_load_ps(b.v.data()), _mm_load_ps(a.v.data())));
    return r;
  }
#endif
  for (size_t k = 0; k < 4; ++k) r.v[k] = std::min(a.v[k], b.v[k]);
  return r;
}
template <bool kSimd>
Lanes lane_max(const Lanes& a, const Lanes& b) {
  Lanes r;
#if defined(__SSE2__)
  if constexpr (kSimd) {
    _mm_store_ps(r.v.data(), _mm_max_ps(_mm_load_ps(b.v.data()), _mm_load_ps(a.v.data())));
    return r;
  }
#endif
  for (size_t k = 0; k < 4; ++k) r.v[k] = std::max(a.v[k], b.v[k]);
  return r;
}

// An empty box in lanes: the identity of the union.
constexpr float kEmptyLo = std::numeric_limits<float>::infinity();
struct LaneBox {
  Lanes lo{{kEmptyLo, kEmptyLo, kEmptyLo, kEmptyLo}};
  Lanes hi{{-kEmptyLo, -kEmptyLo, -kEmptyLo, -kEmptyLo}};
  template <bool kSimd>
  void extend(const Lanes& l, const Lanes& h) {
    lo = lane_min<kSimd>(lo, l);
    hi = lane_max<kSimd>(hi, h);
  }
  template <bool kSimd>
  void extend(const LaneBox& b) {
    extend<kSimd>(b.lo, b.hi);
  }
  // Empty: BBox's own empty value (infinities the other way round), as the lanes start.
  BBox box() const { return BBox{{lo.v[0], lo.v[1], lo.v[2]}, {hi.v[0], hi.v[1], hi.v[2]}}; }
};

// One SAH bin: the boxes and centroids of the primitives whose centroid falls in it.
struct Bin {
  LaneBox box;
  uint32_t count = 0;
};

// Where a range splits: the axis, the first primitive of the right side, and both sides' bounds.
struct Split {
  int axis = -1;
  uint32_t mid = 0;
  RangeBounds left, right;
};

// A primitive as the build moves it: its box and its index, 32 bytes. The build partitions these
// in place, so that a node's primitives lie together in memory (with indices into the scene's
// boxes every pass gathered from all over them: most of the build's time went to those cache
// misses). The index rides in the low row's unused lane as raw bits: bounds never read that lane,
// and no arithmetic touches it (the centroid is computed on x, y, z only: as floats the bits are
// denormals, which would stall additions).
struct alignas(16) PrimRef {
  Lanes lo, hi;
  uint32_t id() const { return std::bit_cast<uint32_t>(lo.v[3]); }
  // BBox::center()'s expression per axis: the bins are those of centroids stored apart.
  template <bool kSimd>
  Lanes centroid() const {
    Lanes c{{0.0f, 0.0f, 0.0f, 0.0f}};
#if defined(__SSE2__)
    if constexpr (kSimd) {
      // The index's lane masked to 0 first (hi's is 0): one add and one multiply per lane, as below.
      const __m128 x_y_z = _mm_castsi128_ps(_mm_set_epi32(0, -1, -1, -1));
      const __m128 l = _mm_and_ps(_mm_load_ps(lo.v.data()), x_y_z);
      _mm_store_ps(c.v.data(), _mm_mul_ps(_mm_add_ps(l, _mm_load_ps(hi.v.data())), _mm_set1_ps(0.5f)));
      return c;
    }
#endif
    for (size_t k = 0; k < 3; ++k) c.v[k] = (lo.v[k] + hi.v[k]) * 0.5f;
    return c;
  }
  static PrimRef of(const BBox& b, uint32_t id) {
    PrimRef r;
    r.lo = {{b.lo.x, b.lo.y, b.lo.z, std::bit_cast<float>(id)}};
    r.hi = {{b.hi.x, b.hi.y, b.hi.z, 0.0f}};
    return r;
  }
};
static_assert(sizeof(PrimRef) == 32);

// The binary tree's nodes in depth-first order, kept as chunks: a subtree built in parallel is a
// list of its own, spliced in by moving its chunks. (Appending such subtrees into their parent's
// array copied every node once per parallel level above it, and held the tree twice at the
// root.) A node is found by its chunk and position, which splicing does not move.
class NodeList {
 public:
  struct Slot {
    size_t chunk = 0, index = 0;
  };
  size_t size() const { return size_; }
  Slot push(const BvhNode& node) {
    chunks_.back().push_back(node);
    ++size_;
    return Slot{chunks_.size() - 1, chunks_.back().size() - 1};
  }
  BvhNode& operator[](const Slot& s) { return chunks_[s.chunk][s.index]; }
  void splice(NodeList&& other) {
    size_ += other.size_;
    for (std::vector<BvhNode>& c : other.chunks_)
      if (!c.empty()) chunks_.push_back(std::move(c));
    chunks_.emplace_back();
  }
  // The nodes in one array, each chunk freed once copied.
  std::vector<BvhNode> take() {
    std::vector<BvhNode> all;
    all.reserve(size_);
    for (std::vector<BvhNode>& c : chunks_) {
      all.insert(all.end(), c.begin(), c.end());
      std::vector<BvhNode>().swap(c);
    }
    return all;
  }

 private:
  std::vector<std::vector<BvhNode>> chunks_ = std::vector<std::vector<BvhNode>>(1);
  size_t size_ = 0;
};

// The build makes one pass over a node's primitives to bin them on all three axes at once, and
// each child gets its bounds from the bins of its side instead of from another pass over its
// primitives (unions of boxes are exact, so they are the boxes such a pass would find): per
// level, one pass and the partition, where binning each axis and then bounding each child took
// five passes. The tree is the one those passes made, bit for bit (std::partition moves PrimRefs
// as it moved indices).
template <bool kSimd>
struct Builder {
  std::vector<PrimRef>& refs;

  RangeBounds bounds_of(uint32_t begin, uint32_t end) const {
    LaneBox box, cbox;
    for (uint32_t i = begin; i < end; ++i) {
      box.extend<kSimd>(refs[i].lo, refs[i].hi);
      const Lanes c = refs[i].template centroid<kSimd>();
      cbox.extend<kSimd>(c, c);
    }
    return RangeBounds{box.box(), cbox.box()};
  }

  // Appends the subtree over refs[begin, end), whose bounds are `bounds`, to `out` (interior
  // offsets relative to the node; leaf offsets are absolute indices into prims).
  void build(uint32_t begin, uint32_t end, const RangeBounds& bounds, NodeList& out) {
    const uint32_t n = end - begin;
    const size_t self = out.size();
    const NodeList::Slot slot = out.push(BvhNode{bounds.box, begin, uint16_t(n), 0, 0});
    if (n <= 1) return;
    Split split;
    if (!choose_split(begin, end, bounds, split)) {
      if (n <= kMaxLeafSize) return;
      // No useful split (coincident centroids, or the SAH prefers a leaf that is too big):
      // halve by index, which keeps leaves small and the tree deterministic.
      split.axis = 0;
      split.mid = begin + n / 2;
      split.left = bounds_of(begin, split.mid);
      split.right = bounds_of(split.mid, end);
    }
    out[slot].count = 0;
    out[slot].axis = uint8_t(split.axis);
    if (n > kParallelThreshold) {
      NodeList left, right;
      tbb::parallel_invoke([&] { build(begin, split.mid, split.left, left); },
                           [&] { build(split.mid, end, split.right, right); });
      out.splice(std::move(left));
      out[slot].offset = uint32_t(out.size() - self);
      out.splice(std::move(right));
    } else {
      build(begin, split.mid, split.left, out);
      out[slot].offset = uint32_t(out.size() - self);
      build(split.mid, end, split.right, out);
    }
  }

  // The best binned SAH split of refs[begin, end); partitions the range, sets both sides'
  // bounds and returns true when splitting beats a leaf (or the range is too large for one).
  bool choose_split(uint32_t begin, uint32_t end, const RangeBounds& bounds, Split& split) {
    const uint32_t n = end - begin;
    const BBox& cbox = bounds.cbox;
    std::array<std::array<Bin, kBins>, 3> bins;
    std::array<float, 3> lo{}, scale{};
    std::array<bool, 3> binned{};
    for (int axis = 0; axis < 3; ++axis) {
      lo[size_t(axis)] = cbox.lo[axis];
      const float extent = cbox.hi[axis] - cbox.lo[axis];
      binned[size_t(axis)] = extent > 0.0f;
      scale[size_t(axis)] = binned[size_t(axis)] ? float(kBins) / extent : 0.0f;
    }
    auto bin_of = [&](const Lanes& c, int axis) {
      return std::min(kBins - 1, int((c.v[size_t(axis)] - lo[size_t(axis)]) * scale[size_t(axis)]));
    };
    for (uint32_t i = begin; i < end; ++i) {
      const PrimRef& r = refs[i];
      const Lanes c = r.template centroid<kSimd>();
      for (int axis = 0; axis < 3; ++axis) {
        if (!binned[size_t(axis)]) continue;
        Bin& bin = bins[size_t(axis)][size_t(bin_of(c, axis))];
        bin.box.template extend<kSimd>(r.lo, r.hi);
        ++bin.count;
      }
    }
    float best_cost = std::numeric_limits<float>::infinity();
    int best_bin = -1, best_axis = -1;
    for (int axis = 0; axis < 3; ++axis) {
      if (!binned[size_t(axis)]) continue;
      std::array<BBox, kBins> bin_box;
      for (size_t k = 0; k < size_t(kBins); ++k) bin_box[k] = bins[size_t(axis)][k].box.box();
      const std::array<Bin, kBins>& bin = bins[size_t(axis)];
      // Sweep: cost of splitting after bin k = area(left) * count(left) + area(right) * count(right).
      std::array<float, kBins> right_cost{};
      BBox acc;
      uint32_t count = 0;
      for (int k = kBins - 1; k > 0; --k) {
        acc.extend(bin_box[size_t(k)]);
        count += bin[size_t(k)].count;
        right_cost[size_t(k)] = half_area(acc) * float(count);
      }
      acc = BBox{};
      count = 0;
      for (int k = 0; k < kBins - 1; ++k) {
        acc.extend(bin_box[size_t(k)]);
        count += bin[size_t(k)].count;
        if (count == 0 || count == n) continue;
        float cost = half_area(acc) * float(count) + right_cost[size_t(k + 1)];
        if (cost < best_cost) {
          best_cost = cost;
          best_bin = k;
          best_axis = axis;
        }
      }
    }
    if (best_axis < 0) return false;
    const float parent_area = half_area(bounds.box);
    const float split_cost =
        kTraversalCost + kPrimitiveCost * (parent_area > 0.0f ? best_cost / parent_area : float(n));
    if (n <= kMaxLeafSize && split_cost >= kPrimitiveCost * float(n)) return false;
    split.axis = best_axis;
    split.mid = partition(begin, end, [&](const Lanes& c) { return bin_of(c, best_axis) <= best_bin; }, split);
    return split.mid > begin && split.mid < end;
  }

  // Hoare's partition of refs[begin, end) by `in_left` (of a centroid), as libstdc++'s
  // std::partition does it, so that the tree is the one the build made with it, and a pure
  // function of the boxes whatever the standard library. It judges every primitive exactly once,
  // and then adds it to its side's bounds: the children's bounds come with the partition, not
  // from another pass. Returns the first primitive of the right side.
  template <typename InLeft>
  uint32_t partition(uint32_t begin, uint32_t end, const InLeft& in_left, Split& split) {
    LaneBox box[2], cbox[2];  // [left, right]
    auto judge = [&](const PrimRef& r) {
      const Lanes c = r.template centroid<kSimd>();
      const bool left = in_left(c);
      box[left ? 0 : 1].template extend<kSimd>(r.lo, r.hi);
      cbox[left ? 0 : 1].template extend<kSimd>(c, c);
      return left;
    };
    PrimRef* first = refs.data() + begin;
    PrimRef* last = refs.data() + end;
    while (first != last) {
      if (judge(*first)) {
        ++first;
        continue;
      }
      // *first goes right: from the back, the next one that goes left takes its place.
      bool swapped = false;
      while (first != --last) {
        if (judge(*last)) {
          std::swap(*first, *last);
          ++first;
          swapped = true;
          break;
        }
      }
      if (!swapped) break;
    }
    split.left = RangeBounds{box[0].box(), cbox[0].box()};
    split.right = RangeBounds{box[1].box(), cbox[1].box()};
    return uint32_t(first - refs.data());
  }
};

// Collapses a binary tree into 4-wide nodes: each node takes its binary node's two children and
// keeps opening the child with the largest surface area until it has four.
struct Collapser {
  const std::vector<BvhNode>& binary;
  std::vector<Bvh4Node>& out;

  void set_slot(Bvh4Node& n, int k, const BBox& b) {
    n.boxes.lo_x[k] = b.lo.x;
    n.boxes.lo_y[k] = b.lo.y;
    n.boxes.lo_z[k] = b.lo.z;
    n.boxes.hi_x[k] = b.hi.x;
    n.boxes.hi_y[k] = b.hi.y;
    n.boxes.hi_z[k] = b.hi.z;
    n.valid |= uint8_t(1u << k);
  }

  // Makes the 4-wide node for binary node `b` (an interior node, or a leaf when it is the root
  // of a one-leaf tree) and returns its index.
  uint32_t collapse(uint32_t b) {
    std::vector<uint32_t> kids;
    if (binary[b].count > 0) {
      kids.push_back(b);
    } else {
      kids = {b + 1, binary[b].offset};
      while (kids.size() < 4) {
        int best = -1;
        float best_area = -1.0f;
        for (size_t i = 0; i < kids.size(); ++i)
          if (binary[kids[i]].count == 0 && half_area(binary[kids[i]].box) > best_area) {
            best_area = half_area(binary[kids[i]].box);
            best = int(i);
          }
        if (best < 0) break;  // only leaves left
        uint32_t opened = kids[size_t(best)];
        kids[size_t(best)] = opened + 1;
        kids.insert(kids.begin() + best + 1, binary[opened].offset);
      }
    }
    const uint32_t index = uint32_t(out.size());
    out.emplace_back();
    for (size_t k = 0; k < kids.size(); ++k) {
      const BvhNode& kid = binary[kids[k]];
      set_slot(out[index], int(k), kid.box);
      if (kid.count > 0) {
        out[index].child[k] = kid.offset;
        out[index].count[k] = uint8_t(kid.count);
      } else {
        uint32_t c = collapse(kids[k]);  // may reallocate `out`: index, not a reference
        out[index].child[k] = c;
        out[index].count[k] = 0;
      }
    }
    return index;
  }
};

// The binary tree over `refs` (consumed: reordered, then freed), and the primitives' order.
template <bool kSimd>
std::vector<BvhNode> build_binary(std::vector<PrimRef>& refs, std::vector<uint32_t>& prims) {
  Builder<kSimd> builder{refs};
  NodeList nodes;
  builder.build(0, uint32_t(refs.size()), builder.bounds_of(0, uint32_t(refs.size())), nodes);
  prims.resize(refs.size());
  for (size_t i = 0; i < refs.size(); ++i) prims[i] = refs[i].id();
  std::vector<PrimRef>().swap(refs);
  return nodes.take();
}

}  // namespace

Bvh Bvh::build(std::span<const BBox> prim_bounds, BvhBuildPath path) {
  Bvh bvh;
  std::vector<BvhNode> binary;
  {
    std::vector<PrimRef> refs;
    refs.reserve(prim_bounds.size());
    for (uint32_t i = 0; i < prim_bounds.size(); ++i)
      if (valid_box(prim_bounds[i])) refs.push_back(PrimRef::of(prim_bounds[i], i));
    if (refs.empty()) return bvh;
    binary = path == BvhBuildPath::Simd && kHaveSimd ? build_binary<true>(refs, bvh.prims_)
                                                     : build_binary<false>(refs, bvh.prims_);
  }
  // Offsets of interior nodes were relative to the node; make them absolute.
  for (uint32_t i = 0; i < binary.size(); ++i)
    if (binary[i].count == 0) binary[i].offset += i;
  bvh.bounds_ = binary[0].box;
  bvh.nodes_.reserve(binary.size() / 2 + 1);
  Collapser{binary, bvh.nodes_}.collapse(0);
  bvh.nodes_.shrink_to_fit();
  return bvh;
}

}  // namespace darc
