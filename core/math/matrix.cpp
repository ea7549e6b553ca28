#include "core/math/matrix.h"

#include <cmath>
#include <numbers>

namespace darc {

Matrix4 Matrix4::from_row_major(const double* v) {
  Matrix4 r;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) r.m[i][j] = v[i * 4 + j];
  return r;
}

Matrix4 Matrix4::translate(const Vec3d& d) {
  Matrix4 r;
  r.m[3][0] = d.x;
  r.m[3][1] = d.y;
  r.m[3][2] = d.z;
  return r;
}

Matrix4 Matrix4::scale(const Vec3d& s) {
  Matrix4 r;
  r.m[0][0] = s.x;
  r.m[1][1] = s.y;
  r.m[2][2] = s.z;
  return r;
}

Matrix4 Matrix4::rotate(double degrees, const Vec3d& axis) {
  Vec3d a = normalize(axis);
  Matrix4 r;
  if (length_squared(a) == 0) return r;
  double th = degrees * std::numbers::pi / 180.0;
  double s = std::sin(th), c = std::cos(th), t = 1 - c;
  // Row-vector form of the rotation used by the RI spec (same as the column-vector
  // right-handed rotation matrix, transposed).
  r.m[0][0] = t * a.x * a.x + c;
  r.m[0][1] = t * a.x * a.y + s * a.z;
  r.m[0][2] = t * a.x * a.z - s * a.y;
  r.m[1][0] = t * a.x * a.y - s * a.z;
  r.m[1][1] = t * a.y * a.y + c;
  r.m[1][2] = t * a.y * a.z + s * a.x;
  r.m[2][0] = t * a.x * a.z + s * a.y;
  r.m[2][1] = t * a.y * a.z - s * a.x;
  r.m[2][2] = t * a.z * a.z + c;
  return r;
}

Matrix4 Matrix4::perspective(double fov_degrees) {
  double f = 1.0 / std::tan(fov_degrees * std::numbers::pi / 360.0);
  Matrix4 r;
  r.m[0][0] = f;
  r.m[1][1] = f;
  r.m[2][3] = 1;
  r.m[3][3] = 0;
  return r;
}

Matrix4 operator*(const Matrix4& a, const Matrix4& b) {
  Matrix4 r;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      double s = 0;
      for (int k = 0; k < 4; ++k) s += a.m[i][k] * b.m[k][j];
      r.m[i][j] = s;
    }
  return r;
}

Vec3d Matrix4::transform_point(const Vec3d& p) const {
  double x = p.x * m[0][0] + p.y * m[1][0] + p.z * m[2][0] + m[3][0];
  double y = p.x * m[0][1] + p.y * m[1][1] + p.z * m[2][1] + m[3][1];
  double z = p.x * m[0][2] + p.y * m[1][2] + p.z * m[2][2] + m[3][2];
  double w = p.x * m[0][3] + p.y * m[1][3] + p.z * m[2][3] + m[3][3];
  if (w != 1.0 && w != 0.0) return {x / w, y / w, z / w};
  return {x, y, z};
}

Vec3d Matrix4::transform_vector(const Vec3d& v) const {
  return {v.x * m[0][0] + v.y * m[1][0] + v.z * m[2][0], v.x * m[0][1] + v.y * m[1][1] + v.z * m[2][1],
          v.x * m[0][2] + v.y * m[1][2] + v.z * m[2][2]};
}

Vec3d Matrix4::transform_normal_by_inverse(const Vec3d& n) const {
  // n' = M^-T n in column form = (inverse rows dotted with n).
  return {m[0][0] * n.x + m[0][1] * n.y + m[0][2] * n.z, m[1][0] * n.x + m[1][1] * n.y + m[1][2] * n.z,
          m[2][0] * n.x + m[2][1] * n.y + m[2][2] * n.z};
}

double Matrix4::determinant() const {
  const auto& a = m;
  double s0 = a[0][0] * a[1][1] - a[1][0] * a[0][1];
  double s1 = a[0][0] * a[1][2] - a[1][0] * a[0][2];
  double s2 = a[0][0] * a[1][3] - a[1][0] * a[0][3];
  double s3 = a[0][1] * a[1][2] - a[1][1] * a[0][2];
  double s4 = a[0][1] * a[1][3] - a[1][1] * a[0][3];
  double s5 = a[0][2] * a[1][3] - a[1][2] * a[0][3];
  double c5 = a[2][2] * a[3][3] - a[3][2] * a[2][3];
  double c4 = a[2][1] * a[3][3] - a[3][1] * a[2][3];
  double c3 = a[2][1] * a[3][2] - a[3][1] * a[2][2];
  double c2 = a[2][0] * a[3][3] - a[3][0] * a[2][3];
  double c1 = a[2][0] * a[3][2] - a[3][0] * a[2][2];
  double c0 = a[2][0] * a[3][1] - a[3][0] * a[2][1];
  return s0 * c5 - s1 * c4 + s2 * c3 + s3 * c2 - s4 * c1 + s5 * c0;
}

bool Matrix4::inverse(Matrix4& out) const {
  const auto& a = m;
  double s0 = a[0][0] * a[1][1] - a[1][0] * a[0][1];
  double s1 = a[0][0] * a[1][2] - a[1][0] * a[0][2];
  double s2 = a[0][0] * a[1][3] - a[1][0] * a[0][3];
  double s3 = a[0][1] * a[1][2] - a[1][1] * a[0][2];
  double s4 = a[0][1] * a[1][3] - a[1][1] * a[0][3];
  double s5 = a[0][2] * a[1][3] - a[1][2] * a[0][3];
  double c5 = a[2][2] * a[3][3] - a[3][2] * a[2][3];
  double c4 = a[2][1] * a[3][3] - a[3][1] * a[2][3];
  double c3 = a[2][1] * a[3][2] - a[3][1] * a[2][2];
  double c2 = a[2][0] * a[3][3] - a[3][0] * a[2][3];
  double c1 = a[2][0] * a[3][2] - a[3][0] * a[2][2];
  double c0 = a[2][0] * a[3][1] - a[3][0] * a[2][1];
  double det = s0 * c5 - s1 * c4 + s2 * c3 + s3 * c2 - s4 * c1 + s5 * c0;
  if (det == 0 || !std::isfinite(det)) {
    out = Matrix4{};
    return false;
  }
  double inv = 1.0 / det;
  auto& b = out.m;
  b[0][0] = (a[1][1] * c5 - a[1][2] * c4 + a[1][3] * c3) * inv;
  b[0][1] = (-a[0][1] * c5 + a[0][2] * c4 - a[0][3] * c3) * inv;
  b[0][2] = (a[3][1] * s5 - a[3][2] * s4 + a[3][3] * s3) * inv;
  b[0][3] = (-a[2][1] * s5 + a[2][2] * s4 - a[2][3] * s3) * inv;
  b[1][0] = (-a[1][0] * c5 + a[1][2] * c2 - a[1][3] * c1) * inv;
  b[1][1] = (a[0][0] * c5 - a[0][2] * c2 + a[0][3] * c1) * inv;
  b[1][2] = (-a[3][0] * s5 + a[3][2] * s2 - a[3][3] * s1) * inv;
  b[1][3] = (a[2][0] * s5 - a[2][2] * s2 + a[2][3] * s1) * inv;
  b[2][0] = (a[1][0] * c4 - a[1][1] * c2 + a[1][3] * c0) * inv;
  b[2][1] = (-a[0][0] * c4 + a[0][1] * c2 - a[0][3] * c0) * inv;
  b[2][2] = (a[3][0] * s4 - a[3][1] * s2 + a[3][3] * s0) * inv;
  b[2][3] = (-a[2][0] * s4 + a[2][1] * s2 - a[2][3] * s0) * inv;
  b[3][0] = (-a[1][0] * c3 + a[1][1] * c1 - a[1][2] * c0) * inv;
  b[3][1] = (a[0][0] * c3 - a[0][1] * c1 + a[0][2] * c0) * inv;
  b[3][2] = (-a[3][0] * s3 + a[3][1] * s1 - a[3][2] * s0) * inv;
  b[3][3] = (a[2][0] * s3 - a[2][1] * s1 + a[2][2] * s0) * inv;
  return true;
}

Matrix4 Matrix4::inverse() const {
  Matrix4 r;
  inverse(r);
  return r;
}

}  // namespace darc
