// Small fixed-size vectors. Vec3f is the hot-loop type; Vec3d is used where transforms
// are composed and where precision matters more than speed.
#pragma once

#include <algorithm>
#include <cmath>

namespace darc {

template <typename T>
struct Vec3T {
  T x = 0, y = 0, z = 0;

  constexpr Vec3T() = default;
  constexpr Vec3T(T x_, T y_, T z_) : x(x_), y(y_), z(z_) {}
  template <typename U>
  constexpr explicit Vec3T(const Vec3T<U>& o) : x(T(o.x)), y(T(o.y)), z(T(o.z)) {}

  constexpr T operator[](int i) const { return i == 0 ? x : (i == 1 ? y : z); }
  constexpr T& operator[](int i) { return i == 0 ? x : (i == 1 ? y : z); }

  constexpr Vec3T operator+(const Vec3T& o) const { return {x + o.x, y + o.y, z + o.z}; }
  constexpr Vec3T operator-(const Vec3T& o) const { return {x - o.x, y - o.y, z - o.z}; }
  constexpr Vec3T operator-() const { return {-x, -y, -z}; }
  constexpr Vec3T operator*(T s) const { return {x * s, y * s, z * s}; }
  constexpr Vec3T operator/(T s) const { return {x / s, y / s, z / s}; }
  constexpr Vec3T& operator+=(const Vec3T& o) { x += o.x; y += o.y; z += o.z; return *this; }
  constexpr Vec3T& operator-=(const Vec3T& o) { x -= o.x; y -= o.y; z -= o.z; return *this; }
  constexpr Vec3T& operator*=(T s) { x *= s; y *= s; z *= s; return *this; }
  constexpr bool operator==(const Vec3T&) const = default;
};

template <typename T>
constexpr Vec3T<T> operator*(T s, const Vec3T<T>& v) { return v * s; }

template <typename T>
constexpr T dot(const Vec3T<T>& a, const Vec3T<T>& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }

template <typename T>
constexpr Vec3T<T> cross(const Vec3T<T>& a, const Vec3T<T>& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

template <typename T>
constexpr Vec3T<T> mul(const Vec3T<T>& a, const Vec3T<T>& b) { return {a.x * b.x, a.y * b.y, a.z * b.z}; }

template <typename T>
inline T length(const Vec3T<T>& v) { return std::sqrt(dot(v, v)); }

template <typename T>
constexpr T length_squared(const Vec3T<T>& v) { return dot(v, v); }

// Returns v / |v|, or the zero vector when |v| == 0 (never NaN).
template <typename T>
inline Vec3T<T> normalize(const Vec3T<T>& v) {
  T l = length(v);
  return l > T(0) ? v / l : Vec3T<T>{};
}

template <typename T>
constexpr Vec3T<T> min(const Vec3T<T>& a, const Vec3T<T>& b) {
  return {std::min(a.x, b.x), std::min(a.y, b.y), std::min(a.z, b.z)};
}
template <typename T>
constexpr Vec3T<T> max(const Vec3T<T>& a, const Vec3T<T>& b) {
  return {std::max(a.x, b.x), std::max(a.y, b.y), std::max(a.z, b.z)};
}
template <typename T>
constexpr Vec3T<T> lerp(T t, const Vec3T<T>& a, const Vec3T<T>& b) { return a * (T(1) - t) + b * t; }

template <typename T>
constexpr T max_component(const Vec3T<T>& v) { return std::max(v.x, std::max(v.y, v.z)); }

template <typename T>
inline Vec3T<T> abs(const Vec3T<T>& v) { return {std::abs(v.x), std::abs(v.y), std::abs(v.z)}; }

// An orthonormal basis (s, t) perpendicular to the unit vector n (Duff et al. 2017).
template <typename T>
inline void orthonormal_basis(const Vec3T<T>& n, Vec3T<T>& s, Vec3T<T>& t) {
  T sign = std::copysign(T(1), n.z);
  T a = T(-1) / (sign + n.z);
  T b = n.x * n.y * a;
  s = {T(1) + sign * n.x * n.x * a, sign * b, -sign * n.x};
  t = {b, sign + n.y * n.y * a, -n.y};
}

using Vec3f = Vec3T<float>;
using Vec3d = Vec3T<double>;

struct Vec2f {
  float x = 0, y = 0;
  bool operator==(const Vec2f&) const = default;
};

}  // namespace darc
