// Every curve strand of a scene as cubic Bézier segments in world space, stored as a structure
// of arrays laid out for the intersection loop. Convention: u runs ALONG a segment (0 at its
// first control point), v ACROSS the ribbon (RIB calls these v and u respectively).
//
// What a segment costs (docs/performance-640.md, "Memory"): 48 bytes of control points, 16 of
// width, 4 + 4 of strand and attribute ids, 4 of shading index, 1 of flags; colour, opacity and
// texture coordinates are stored once per distinct value (a Curves call without Cs/Os/st shares
// one entry; st varying along strands makes one per segment: 128 bytes), end normals
// only when some segment is oriented.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

#include "core/math/bbox.h"
#include "core/math/vec.h"

namespace darc {

// The motion record of a segment that does not move.
inline constexpr uint32_t kStaticSegment = std::numeric_limits<uint32_t>::max();

// How a moving segment's keys are stored (CurveSet::motions): its key times start at
// motion_times[times], its control points at motion_cp[points] (4 per key).
struct SegmentMotion {
  uint32_t times = 0;
  uint32_t keys = 0;
  uint32_t points = 0;
};

// The most keys a moving segment has: a motion block's 64 times, and shutter open and close.
inline constexpr size_t kMaxCurveMotionKeys = 66;

// A strand id no strand has (surfaces, or "skip no strand").
inline constexpr uint32_t kNoStrand = std::numeric_limits<uint32_t>::max();

inline constexpr size_t kControlPointsPerSegment = 4;  // a cubic Bézier
inline constexpr size_t kNormalsPerSegment = 2;        // one at each end of the segment

// The Bézier coefficients of a segment's colour (Cs), opacity (Os) and texture coordinates (s, t:
// the "st" or "s" and "t" primvars; 0 without them). Uniform st (a scalp map) shares one entry
// along a strand; st that varies along it makes an entry per segment.
struct SegmentShading {
  std::array<Vec3f, 4> cs{Vec3f{1, 1, 1}, Vec3f{1, 1, 1}, Vec3f{1, 1, 1}, Vec3f{1, 1, 1}};
  std::array<Vec3f, 4> os{Vec3f{1, 1, 1}, Vec3f{1, 1, 1}, Vec3f{1, 1, 1}, Vec3f{1, 1, 1}};
  std::array<float, 4> s{}, t{};
  bool operator==(const SegmentShading&) const = default;
};

// Per-segment flag bits.
enum SegmentFlag : uint8_t {
  kSegmentOriented = 1,     // the ribbon is perpendicular to its end normals (else it faces the ray)
  kSegmentStrandStart = 2,  // its u = 0 end is the strand's first end
  kSegmentStrandEnd = 4,    // its u = 1 end is the strand's last end
};

struct CurveSet {
  // Per segment i, entries [4i, 4i+4) of the 4-per-segment arrays.
  std::vector<Vec3f> cp;     // world-space Bézier control points
  std::vector<float> width;  // Bézier coefficients of the world-space width (<= 0 where hidden)
  std::vector<uint32_t> shading_index;  // per segment: its entry in `shading`
  std::vector<SegmentShading> shading;  // distinct colour and opacity coefficients
  // Entries [2i, 2i+2): world-space unit normals at u = 0 and u = 1. Empty while no segment is
  // oriented; zero for segments that are not.
  std::vector<Vec3f> normal;
  std::vector<uint8_t> flags;          // SegmentFlag bits
  std::vector<uint32_t> strand_id;     // unique per curve in the scene
  std::vector<uint32_t> attribute_id;  // the attribute state (material) the segment was made with
  // Motion blur: segments that move during the shutter keep their control points at each of their
  // key times (shutter-normalised: 0 at open, 1 at close; the first key at 0, the last at 1) and
  // move linearly between keys; `cp` holds their points at shutter open. Widths, normals and
  // colours do not move. `motion` is empty while no segment moves, else per segment an index
  // into `motions` or kStaticSegment. Key times are shared by the segments of one request.
  std::vector<uint32_t> motion;
  std::vector<SegmentMotion> motions;
  std::vector<float> motion_times;
  std::vector<Vec3f> motion_cp;

  size_t size() const { return strand_id.size(); }
  // Bounds of the control-point hull grown by half the largest |width| coefficient (the Bézier
  // width lies in the hull of its coefficients, so this bounds the whole ribbon).
  BBox segment_bounds(size_t i) const;
  // The sub-arrays of segment i.
  const Vec3f* control_points(size_t i) const { return cp.data() + i * kControlPointsPerSegment; }
  const float* widths(size_t i) const { return width.data() + i * kControlPointsPerSegment; }
  const Vec3f* colors(size_t i) const { return shading[shading_index[i]].cs.data(); }
  const Vec3f* opacities(size_t i) const { return shading[shading_index[i]].os.data(); }
  const SegmentShading& segment_shading(size_t i) const { return shading[shading_index[i]]; }
  bool oriented(size_t i) const { return (flags[i] & kSegmentOriented) != 0; }
  // The unit normal at end k (0: u = 0, 1: u = 1) of an oriented segment.
  Vec3f end_normal(size_t i, int k) const { return normal[i * kNormalsPerSegment + size_t(k)]; }
  bool moving(size_t i) const { return !motion.empty() && motion[i] != kStaticSegment; }
  bool has_motion() const { return !motions.empty(); }
  // The control points at shutter time `time` in [0, 1]: `cp`'s for a segment that does not
  // move, else interpolated into `scratch`.
  const Vec3f* control_points_at(size_t i, float time, Vec3f scratch[4]) const;
  bool strand_start(size_t i) const { return (flags[i] & kSegmentStrandStart) != 0; }
  bool strand_end(size_t i) const { return (flags[i] & kSegmentStrandEnd) != 0; }

  // Appends one segment (its strand-end flags are set by mark_strand_ends). `normals` null: the
  // ribbon faces the ray.
  void add_segment(const std::array<Vec3f, 4>& points, const std::array<float, 4>& widths, uint32_t strand,
                   uint32_t attribute, const SegmentShading& colours = {}, const Vec3f* normals = nullptr);
  // Appends every segment of `other` (built on its own, strand ids from 0) with the attribute
  // `attribute` and its strand ids moved up by `strand_offset`: the same arrays as building
  // them here (colours are shared with the previous segment's entry when equal, as add_segment does).
  void append(const CurveSet& other, uint32_t attribute, uint32_t strand_offset);
  // Makes segments [first, size()) move: `keys[k]` holds the same segments (same count and order,
  // from the same request) at shutter time times[k]; times increase from 0 to 1. The points at
  // time 0 must be those already in `cp`. Segments whose keys are all equal stay static.
  void add_motion(size_t first, const std::vector<float>& times, const std::vector<const CurveSet*>& keys);
  // Sets the strand-start and strand-end flags of segments [first, size()) from their strand ids:
  // a strand's first and last segments, unless the strand is closed (its first point is its last).
  void mark_strand_ends(size_t first);
  // Releases the slack the arrays grew with while segments were appended.
  void shrink_to_fit();
  // Bytes held (capacity), for the memory report.
  size_t memory_bytes() const;
};

}  // namespace darc
