// Every curve strand of a scene as cubic Bézier segments in world space, stored as a structure
// of arrays laid out for the intersection loop. Convention: u runs ALONG a segment (0 at its
// first control point), v ACROSS the ribbon (RIB calls these v and u respectively).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/bbox.h"
#include "core/vec.h"

namespace darc {

inline constexpr size_t kControlPointsPerSegment = 4;  // a cubic Bézier
inline constexpr size_t kNormalsPerSegment = 2;        // one at each end of the segment

struct CurveSet {
  // Per segment i, entries [4i, 4i+4) of the 4-per-segment arrays.
  std::vector<Vec3f> cp;     // world-space Bézier control points
  std::vector<float> width;  // Bézier coefficients of the world-space width (<= 0 where hidden)
  std::vector<Vec3f> cs;     // Bézier coefficients of the colour
  std::vector<Vec3f> os;     // Bézier coefficients of the opacity
  // Entries [2i, 2i+2): world-space unit normals at u = 0 and u = 1; zero when !oriented[i].
  std::vector<Vec3f> normal;
  std::vector<uint8_t> oriented;            // 1: ribbon perpendicular to `normal`; 0: faces the ray
  std::vector<uint32_t> strand_id;          // unique per curve in the scene
  std::vector<uint32_t> segment_in_strand;  // index of the segment in its curve (before any was dropped)
  std::vector<uint32_t> attribute_id;       // the attribute state (material) the segment was made with

  size_t size() const { return strand_id.size(); }
  // Bounds of the control-point hull grown by half the largest |width| coefficient (the Bézier
  // width lies in the hull of its coefficients, so this bounds the whole ribbon).
  BBox segment_bounds(size_t i) const;
  // The sub-arrays of segment i.
  const Vec3f* control_points(size_t i) const { return cp.data() + i * kControlPointsPerSegment; }
  const float* widths(size_t i) const { return width.data() + i * kControlPointsPerSegment; }
};

}  // namespace darc
