#include "core/geometry/curves/curve_set.h"

#include <cmath>

namespace darc {

BBox CurveSet::segment_bounds(size_t i) const {
  BBox box;
  const Vec3f* p = control_points(i);
  const float* w = widths(i);
  float max_width = 0.0f;
  for (size_t k = 0; k < kControlPointsPerSegment; ++k) {
    box.extend(p[k]);
    max_width = std::max(max_width, std::abs(w[k]));
  }
  return box.expanded(0.5f * max_width);
}

void CurveSet::add_segment(const std::array<Vec3f, 4>& points, const std::array<float, 4>& widths, uint32_t strand,
                           uint32_t attribute, const SegmentShading& colours, const Vec3f* normals) {
  const size_t i = size();
  cp.insert(cp.end(), points.begin(), points.end());
  width.insert(width.end(), widths.begin(), widths.end());
  // Neighbouring segments usually share their colours (one Curves call, one Color): one entry.
  if (shading.empty() || !(shading.back() == colours)) shading.push_back(colours);
  shading_index.push_back(uint32_t(shading.size() - 1));
  uint8_t f = 0;
  if (normals) {
    f |= kSegmentOriented;
    normal.resize(kNormalsPerSegment * i, Vec3f{});  // the earlier segments' (zero) normals
    normal.push_back(normals[0]);
    normal.push_back(normals[1]);
  } else if (!normal.empty()) {
    normal.push_back(Vec3f{});
    normal.push_back(Vec3f{});
  }
  flags.push_back(f);
  strand_id.push_back(strand);
  attribute_id.push_back(attribute);
}

void CurveSet::append(const CurveSet& other, uint32_t attribute, uint32_t strand_offset) {
  const size_t first = size(), n = other.size();
  cp.insert(cp.end(), other.cp.begin(), other.cp.end());
  width.insert(width.end(), other.width.begin(), other.width.end());
  for (size_t i = 0; i < n; ++i) {
    const SegmentShading& colours = other.shading[other.shading_index[i]];
    if (shading.empty() || !(shading.back() == colours)) shading.push_back(colours);
    shading_index.push_back(uint32_t(shading.size() - 1));
  }
  if (!other.normal.empty()) {
    normal.resize(kNormalsPerSegment * first, Vec3f{});
    normal.insert(normal.end(), other.normal.begin(), other.normal.end());
  } else if (!normal.empty()) {
    normal.resize(kNormalsPerSegment * (first + n), Vec3f{});
  }
  flags.insert(flags.end(), other.flags.begin(), other.flags.end());
  for (size_t i = 0; i < n; ++i) strand_id.push_back(other.strand_id[i] + strand_offset);
  attribute_id.resize(first + n, attribute);
}

void CurveSet::mark_strand_ends(size_t first) {
  const size_t n = size();
  size_t begin = first;
  while (begin < n) {
    size_t end = begin + 1;
    while (end < n && strand_id[end] == strand_id[begin]) ++end;
    for (size_t i = begin; i < end; ++i) flags[i] &= uint8_t(~(kSegmentStrandStart | kSegmentStrandEnd));
    // A closed (periodic) strand has no ends: its first point meets its last.
    if (!(control_points(begin)[0] == control_points(end - 1)[3])) {
      flags[begin] |= kSegmentStrandStart;
      flags[end - 1] |= kSegmentStrandEnd;
    }
    begin = end;
  }
}

void CurveSet::shrink_to_fit() {
  cp.shrink_to_fit();
  width.shrink_to_fit();
  shading_index.shrink_to_fit();
  shading.shrink_to_fit();
  normal.shrink_to_fit();
  flags.shrink_to_fit();
  strand_id.shrink_to_fit();
  attribute_id.shrink_to_fit();
}

size_t CurveSet::memory_bytes() const {
  return cp.capacity() * sizeof(Vec3f) + width.capacity() * sizeof(float) +
         shading_index.capacity() * sizeof(uint32_t) + shading.capacity() * sizeof(SegmentShading) +
         normal.capacity() * sizeof(Vec3f) + flags.capacity() + strand_id.capacity() * sizeof(uint32_t) +
         attribute_id.capacity() * sizeof(uint32_t);
}

}  // namespace darc
