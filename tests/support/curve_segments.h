// One-segment curve sets for the tests of the curve intersectors (the exact one and the
// distance-aware one), which probe a single cubic Bézier segment with chosen rays.
#pragma once

#include <array>

#include "core/geometry/curves/curve_set.h"

namespace darc::test {

// A set holding one segment, a whole strand (both ends are strand ends), with the given Bézier
// control points and width coefficients.
CurveSet single_segment(const std::array<Vec3f, 4>& cp, const std::array<float, 4>& width);

// A straight strand along x from (-1, 0, 5) to (1, 0, 5), as an elevated line (so u = (x + 1) / 2).
std::array<Vec3f, 4> straight_x();

// The same width at every control point.
std::array<float, 4> constant_width(float w);

}  // namespace darc::test
