// Where a shutter time falls among a moving primitive's keys (motion blur): keys at increasing
// shutter times, 0 at open and 1 at close, with positions linear between them. Shared by the
// moving triangles (TriangleStore) and points (PointSet).
#pragma once

#include <algorithm>
#include <cstdint>

namespace darc {

// The key interval holding `time` (clamped to [0, 1]) among times[0..count) (count >= 2): its
// first key k and the fraction s through it.
inline void key_interval(const float* times, uint32_t count, float time, uint32_t& k, float& s) {
  time = std::clamp(time, 0.0f, 1.0f);
  k = 0;
  while (k + 2 < count && times[k + 1] <= time) ++k;
  const float span = times[k + 1] - times[k];
  s = span > 0 ? std::clamp((time - times[k]) / span, 0.0f, 1.0f) : 0.0f;
}

}  // namespace darc
