#include "core/math/transform_interpolation.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace darc {

namespace {

using M3 = std::array<std::array<double, 3>, 3>;

M3 upper_left(const Matrix4& m) {
  M3 a;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) a[i][j] = m.m[i][j];
  return a;
}

M3 mul(const M3& a, const M3& b) {
  M3 r{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k) r[i][j] += a[i][k] * b[k][j];
  return r;
}

M3 transpose(const M3& a) {
  M3 r;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) r[i][j] = a[j][i];
  return r;
}

double det(const M3& a) {
  return a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) - a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
         a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
}

bool inverse(const M3& a, M3& out) {
  const double d = det(a);
  if (!(std::abs(d) > 1e-300) || !std::isfinite(d)) return false;
  out[0][0] = (a[1][1] * a[2][2] - a[1][2] * a[2][1]) / d;
  out[0][1] = (a[0][2] * a[2][1] - a[0][1] * a[2][2]) / d;
  out[0][2] = (a[0][1] * a[1][2] - a[0][2] * a[1][1]) / d;
  out[1][0] = (a[1][2] * a[2][0] - a[1][0] * a[2][2]) / d;
  out[1][1] = (a[0][0] * a[2][2] - a[0][2] * a[2][0]) / d;
  out[1][2] = (a[0][2] * a[1][0] - a[0][0] * a[1][2]) / d;
  out[2][0] = (a[1][0] * a[2][1] - a[1][1] * a[2][0]) / d;
  out[2][1] = (a[0][1] * a[2][0] - a[0][0] * a[2][1]) / d;
  out[2][2] = (a[0][0] * a[1][1] - a[0][1] * a[1][0]) / d;
  return true;
}

// A = R S with R orthogonal of determinant +1 (S absorbs a reflection): the rotation by the
// iteration R <- (R + R^-T) / 2, which converges quadratically for a non-singular A.
bool polar(const M3& a, M3& r, M3& s) {
  r = a;
  for (int it = 0; it < 100; ++it) {
    M3 inv;
    if (!inverse(r, inv)) return false;
    const M3 inv_t = transpose(inv);
    M3 next;
    double change = 0;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        next[i][j] = 0.5 * (r[i][j] + inv_t[i][j]);
        change = std::max(change, std::abs(next[i][j] - r[i][j]));
      }
    r = next;
    if (change < 1e-14) break;
  }
  if (det(r) < 0)
    for (auto& row : r)
      for (double& v : row) v = -v;
  s = mul(transpose(r), a);
  return true;
}

struct Quat {
  double w, x, y, z;
};

Quat to_quat(const M3& r) {
  Quat q;
  const double trace = r[0][0] + r[1][1] + r[2][2];
  if (trace > 0) {
    const double s = std::sqrt(trace + 1.0) * 2;
    q = {0.25 * s, (r[2][1] - r[1][2]) / s, (r[0][2] - r[2][0]) / s, (r[1][0] - r[0][1]) / s};
  } else if (r[0][0] > r[1][1] && r[0][0] > r[2][2]) {
    const double s = std::sqrt(1.0 + r[0][0] - r[1][1] - r[2][2]) * 2;
    q = {(r[2][1] - r[1][2]) / s, 0.25 * s, (r[0][1] + r[1][0]) / s, (r[0][2] + r[2][0]) / s};
  } else if (r[1][1] > r[2][2]) {
    const double s = std::sqrt(1.0 + r[1][1] - r[0][0] - r[2][2]) * 2;
    q = {(r[0][2] - r[2][0]) / s, (r[0][1] + r[1][0]) / s, 0.25 * s, (r[1][2] + r[2][1]) / s};
  } else {
    const double s = std::sqrt(1.0 + r[2][2] - r[0][0] - r[1][1]) * 2;
    q = {(r[1][0] - r[0][1]) / s, (r[0][2] + r[2][0]) / s, (r[1][2] + r[2][1]) / s, 0.25 * s};
  }
  return q;
}

M3 from_quat(const Quat& q) {
  const double w = q.w, x = q.x, y = q.y, z = q.z;
  return M3{{{1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)},
             {2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)},
             {2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)}}};
}

Quat slerp(Quat a, Quat b, double s) {
  double c = a.w * b.w + a.x * b.x + a.y * b.y + a.z * b.z;
  if (c < 0) {  // the shorter arc
    b = {-b.w, -b.x, -b.y, -b.z};
    c = -c;
  }
  double wa = 1 - s, wb = s;
  if (c < 0.9995) {
    const double theta = std::acos(std::clamp(c, -1.0, 1.0));
    wa = std::sin((1 - s) * theta) / std::sin(theta);
    wb = std::sin(s * theta) / std::sin(theta);
  }
  Quat q{wa * a.w + wb * b.w, wa * a.x + wb * b.x, wa * a.y + wb * b.y, wa * a.z + wb * b.z};
  const double n = std::sqrt(q.w * q.w + q.x * q.x + q.y * q.y + q.z * q.z);
  return {q.w / n, q.x / n, q.y / n, q.z / n};
}

bool affine(const Matrix4& m) { return m.m[0][3] == 0 && m.m[1][3] == 0 && m.m[2][3] == 0 && m.m[3][3] == 1; }

Matrix4 entrywise(const Matrix4& a, const Matrix4& b, double s) {
  Matrix4 r;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) r.m[i][j] = (1 - s) * a.m[i][j] + s * b.m[i][j];
  return r;
}

}  // namespace

Matrix4 interpolate_transform(const Matrix4& a, const Matrix4& b, double s) {
  if (s <= 0) return a;
  if (s >= 1) return b;
  if (a == b) return a;
  M3 ra, sa, rb, sb;
  if (!affine(a) || !affine(b) || !polar(upper_left(a), ra, sa) || !polar(upper_left(b), rb, sb))
    return entrywise(a, b, s);
  const M3 rot = from_quat(slerp(to_quat(ra), to_quat(rb), s));
  M3 stretch;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) stretch[i][j] = (1 - s) * sa[i][j] + s * sb[i][j];
  const M3 upper = mul(rot, stretch);
  Matrix4 r;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) r.m[i][j] = upper[i][j];
  for (int j = 0; j < 3; ++j) r.m[3][j] = (1 - s) * a.m[3][j] + s * b.m[3][j];
  return r;
}

Matrix4 transform_at(std::span<const TransformKey> keys, double time) {
  if (time <= keys.front().time) return keys.front().m;
  if (time >= keys.back().time) return keys.back().m;
  size_t k = 1;
  while (keys[k].time < time) ++k;
  const TransformKey &a = keys[k - 1], &b = keys[k];
  if (time == b.time) return b.m;
  return interpolate_transform(a.m, b.m, (time - a.time) / (b.time - a.time));
}

std::vector<double> merge_times(std::span<const double> a, std::span<const double> b) {
  std::vector<double> r(a.begin(), a.end());
  r.insert(r.end(), b.begin(), b.end());
  std::sort(r.begin(), r.end());
  r.erase(std::unique(r.begin(), r.end()), r.end());
  return r;
}

}  // namespace darc
