// Transforms that move during the shutter (RI motion blocks around Translate, Rotate, ...):
// keys at increasing times, interpolated between neighbours by decomposing each key into a
// translation, a rotation and a stretch (the polar decomposition, as pbrt-v4 and Cycles do), so
// that a turning object stays rigid half-way instead of shrinking as a lerp of matrices would.
#pragma once

#include "core/math/matrix.h"

#include <span>
#include <vector>

namespace darc {

struct TransformKey {
  double time = 0;
  Matrix4 m;
};

// Between a (s = 0) and b (s = 1): translations and stretches linearly, rotations along the
// shorter arc (slerp). Matrices with a projective part (Perspective) are interpolated entry by
// entry.
Matrix4 interpolate_transform(const Matrix4& a, const Matrix4& b, double s);

// The transform at `time`: the first key before the first time, the last after the last.
// `keys` must be non-empty and sorted by time.
Matrix4 transform_at(std::span<const TransformKey> keys, double time);

// The sorted union of two sorted time lists (equal times once).
std::vector<double> merge_times(std::span<const double> a, std::span<const double> b);

}  // namespace darc
