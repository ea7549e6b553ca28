#include "core/curve_set.h"

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

}  // namespace darc
