// 4x4 matrices in the RenderMan convention: row vectors, so a point transforms as
// p' = [x y z 1] * M and translation sits in m[3][0..2]. Composition order follows the RI
// spec: ConcatTransform(T) makes CTM = T * CTM (T applies to object points first).
#pragma once

#include "core/math/vec.h"

#include <array>

namespace darc {

struct Matrix4 {
  std::array<std::array<double, 4>, 4> m{{{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}}};

  static Matrix4 identity() { return {}; }
  // From 16 numbers in RIB order (row-major).
  static Matrix4 from_row_major(const double* v);
  static Matrix4 translate(const Vec3d& d);
  static Matrix4 scale(const Vec3d& s);
  // Rotation by angle (degrees) about axis, following the RI spec (left-handed rule in a
  // left-handed space, i.e. the same matrix as RiRotate).
  static Matrix4 rotate(double degrees, const Vec3d& axis);
  // RiPerspective: a modelling perspective with the given field of view in degrees.
  static Matrix4 perspective(double fov_degrees);

  // (a * b): apply a first, then b (row vectors).
  friend Matrix4 operator*(const Matrix4& a, const Matrix4& b);

  Vec3d transform_point(const Vec3d& p) const;  // divides by w
  Vec3d transform_vector(const Vec3d& v) const;  // ignores translation
  // Transforms a normal: multiply by the inverse transpose. Call on the inverse matrix.
  Vec3d transform_normal_by_inverse(const Vec3d& n) const;
  double determinant() const;
  // Returns false when singular (result left as identity).
  bool inverse(Matrix4& out) const;
  Matrix4 inverse() const;  // identity when singular
  bool operator==(const Matrix4&) const = default;
};

}  // namespace darc
