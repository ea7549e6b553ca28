#include "support/curve_segments.h"

namespace darc::test {

CurveSet single_segment(const std::array<Vec3f, 4>& cp, const std::array<float, 4>& width) {
  CurveSet set;
  set.add_segment(cp, width, 0, 0);
  set.mark_strand_ends(0);
  return set;
}

std::array<Vec3f, 4> straight_x() { return {Vec3f{-1, 0, 5}, {-1.0f / 3, 0, 5}, {1.0f / 3, 0, 5}, {1, 0, 5}}; }

std::array<float, 4> constant_width(float w) { return {w, w, w, w}; }

}  // namespace darc::test
