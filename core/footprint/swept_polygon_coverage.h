// What a convex planar polygon that moves during a ray's stretch of the shutter covers of the
// footprint (motion blur of surfaces under the distance hider; README, Motion blur).
//
// The stretch [from, to] is cut into kSweptPolygonTimes equal parts; at the middle of each the
// polygon's coverage is the exact one of polygon_coverage, and the fragment's coverage is their
// mean (a box of a moving edge is blurred as a sum of kSweptPolygonTimes exact boxes, not
// sampled). Mask point b stands for one time of the stretch (mask_point_time, the same Latin
// square the moving strands use, scaled into the stretch) and holds where the polygon is in that
// time's part: the pieces of a moving mesh, which partition it at every time, partition the mask
// too, so the A-buffer adds them up without cracks or double coverage. Depth and the shading
// point are the polygon's in the part nearest the stretch's middle that covers anything.
#pragma once

#include "core/footprint/coverage_mask.h"
#include "core/footprint/footprint_frame.h"
#include "core/footprint/polygon_coverage.h"

#include <array>
#include <cmath>
#include <span>

namespace darc {

inline constexpr int kSweptPolygonTimes = 4;

// The mask points that stand for a time in part `part` of kSweptPolygonTimes.
inline CoverageMask swept_polygon_part_points(int part) {
  static const std::array<CoverageMask, kSweptPolygonTimes> parts = [] {
    std::array<CoverageMask, kSweptPolygonTimes> out{};
    for (int b = 0; b < kMaskSide * kMaskSide; ++b)
      out[size_t(int(mask_point_time(b) * float(kSweptPolygonTimes)))] |= CoverageMask{1} << b;
    return out;
  }();
  return parts[size_t(part)];
}

// `corners_at(time, corners)` writes the polygon's corners at a shutter time into `corners`
// and returns how many there are (0: none). `hit_time` is the time the depth and shading point
// belong to.
template <class CornersAt>
bool swept_polygon_coverage(const FootprintFrame& frame, float from, float to, CornersAt&& corners_at,
                            PolygonFootprintHit& hit, float& hit_time) {
  std::array<Vec3f, kMaxPolygonCorners> corners;
  float coverage = 0;
  CoverageMask mask = 0;
  bool found = false;
  float best_distance = 0;
  for (int part = 0; part < kSweptPolygonTimes; ++part) {
    const float middle = (float(part) + 0.5f) / float(kSweptPolygonTimes);
    const float time = from + (to - from) * middle;
    const int count = corners_at(time, corners);
    PolygonFootprintHit h;
    if (count < 3 || !polygon_coverage(frame, std::span<const Vec3f>(corners.data(), size_t(count)), h)) continue;
    coverage += h.coverage;
    mask |= h.mask & swept_polygon_part_points(part);
    const float distance = std::abs(middle - 0.5f);
    if (!found || distance < best_distance) {
      const float t_near = found ? std::min(hit.t_near, h.t_near) : h.t_near;
      const float t_far = found ? std::max(hit.t_far, h.t_far) : h.t_far;
      hit = h;
      hit.t_near = t_near;
      hit.t_far = t_far;
      hit_time = time;
      best_distance = distance;
    } else {
      hit.t_near = std::min(hit.t_near, h.t_near);
      hit.t_far = std::max(hit.t_far, h.t_far);
    }
    found = true;
  }
  if (!found) return false;
  hit.coverage = coverage / float(kSweptPolygonTimes);
  hit.mask = mask;
  return hit.coverage > 0 || mask != 0;
}

}  // namespace darc
