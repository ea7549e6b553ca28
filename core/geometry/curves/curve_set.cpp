#include "core/geometry/curves/curve_set.h"

#include <algorithm>
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
  // A moving segment lies between its keys in the hull of the two keys' points (linear motion of
  // each point, a Bezier segment in its control points' hull): the keys' box bounds every time.
  if (moving(i)) {
    const SegmentMotion& m = motions[motion[i]];
    for (uint32_t k = 0; k < m.keys * kControlPointsPerSegment; ++k) box.extend(motion_cp[m.points + k]);
  }
  return box.expanded(0.5f * max_width);
}

const Vec3f* CurveSet::control_points_at(size_t i, float time, Vec3f scratch[4]) const {
  if (!moving(i)) return control_points(i);
  const SegmentMotion& m = motions[motion[i]];
  const float* times = motion_times.data() + m.times;
  uint32_t k = 1;
  while (k + 1 < m.keys && times[k] < time) ++k;
  const float span = times[k] - times[k - 1];
  const float s = span > 0.0f ? std::clamp((time - times[k - 1]) / span, 0.0f, 1.0f) : 1.0f;
  const Vec3f* a = motion_cp.data() + m.points + (k - 1) * kControlPointsPerSegment;
  const Vec3f* b = a + kControlPointsPerSegment;
  for (size_t j = 0; j < kControlPointsPerSegment; ++j) scratch[j] = s == 1.0f ? b[j] : s == 0.0f ? a[j] : lerp(s, a[j], b[j]);
  return scratch;
}

void CurveSet::add_motion(size_t first, const std::vector<float>& times, const std::vector<const CurveSet*>& keys) {
  const size_t n = size();
  const uint32_t times_at = uint32_t(motion_times.size());
  bool times_used = false;
  for (size_t i = first; i < n; ++i) {
    const size_t local = i - first;
    bool moves = false;
    for (const CurveSet* key : keys)
      for (size_t j = 0; j < kControlPointsPerSegment; ++j)
        moves = moves || !(key->control_points(local)[j] == control_points(i)[j]);
    if (!moves) continue;
    motion.resize(n, kStaticSegment);
    if (!times_used) {
      motion_times.insert(motion_times.end(), times.begin(), times.end());
      times_used = true;
    }
    motion[i] = uint32_t(motions.size());
    motions.push_back({times_at, uint32_t(keys.size()), uint32_t(motion_cp.size())});
    for (const CurveSet* key : keys)
      motion_cp.insert(motion_cp.end(), key->control_points(local), key->control_points(local) + kControlPointsPerSegment);
  }
  if (!motion.empty()) motion.resize(n, kStaticSegment);
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
  if (!motion.empty()) motion.push_back(kStaticSegment);
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
  if (other.has_motion()) {
    const uint32_t times_at = uint32_t(motion_times.size()), points_at = uint32_t(motion_cp.size()),
                   motions_at = uint32_t(motions.size());
    motion_times.insert(motion_times.end(), other.motion_times.begin(), other.motion_times.end());
    motion_cp.insert(motion_cp.end(), other.motion_cp.begin(), other.motion_cp.end());
    for (SegmentMotion m : other.motions) motions.push_back({m.times + times_at, m.keys, m.points + points_at});
    motion.resize(first, kStaticSegment);
    for (size_t i = 0; i < n; ++i)
      motion.push_back(other.motion[i] == kStaticSegment ? kStaticSegment : other.motion[i] + motions_at);
  } else if (!motion.empty()) {
    motion.resize(first + n, kStaticSegment);
  }
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
  motion.shrink_to_fit();
  motions.shrink_to_fit();
  motion_times.shrink_to_fit();
  motion_cp.shrink_to_fit();
}

size_t CurveSet::memory_bytes() const {
  return cp.capacity() * sizeof(Vec3f) + width.capacity() * sizeof(float) +
         shading_index.capacity() * sizeof(uint32_t) + shading.capacity() * sizeof(SegmentShading) +
         normal.capacity() * sizeof(Vec3f) + flags.capacity() + strand_id.capacity() * sizeof(uint32_t) +
         attribute_id.capacity() * sizeof(uint32_t) + motion.capacity() * sizeof(uint32_t) +
         motions.capacity() * sizeof(SegmentMotion) + motion_times.capacity() * sizeof(float) +
         motion_cp.capacity() * sizeof(Vec3f);
}

}  // namespace darc
