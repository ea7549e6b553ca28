#include "core/geometry/surfaces/triangle_store.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace darc {

namespace {

constexpr uint8_t kHasNormals = 1, kHasParameters = 2;

// Relative outward padding of a triangle's float bounds: the double-precision hit may lie a few
// float ulps outside the box of its rounded corners.
constexpr float kBoundsRelativePadding = 4.0f * std::numeric_limits<float>::epsilon();

bool finite(const Vec3f& p) { return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z); }

}  // namespace

size_t TriangleStore::add(const TriangleMeshData& world, std::optional<uint32_t> layer) {
  const uint32_t base = uint32_t(P_.size());
  const size_t n = world.P.size();
  const bool has_normals = world.N.size() == n, has_uv = world.uv.size() == n;
  P_.insert(P_.end(), world.P.begin(), world.P.end());
  if (has_normals) {
    N_.resize(base, Vec3f{});
    N_.insert(N_.end(), world.N.begin(), world.N.end());
  }
  if (has_uv) {
    uv_.resize(base, Vec2f{});
    uv_.insert(uv_.end(), world.uv.begin(), world.uv.end());
  }
  size_t kept = 0;
  for (size_t t = 0; t + 2 < world.indices.size(); t += 3) {
    const uint32_t a = world.indices[t], b = world.indices[t + 1], c = world.indices[t + 2];
    if (a >= n || b >= n || c >= n) continue;
    const Vec3f& pa = world.P[a];
    const Vec3f& pb = world.P[b];
    const Vec3f& pc = world.P[c];
    if (!finite(pa) || !finite(pb) || !finite(pc)) continue;
    const Vec3d normal = cross(Vec3d(pb) - Vec3d(pa), Vec3d(pc) - Vec3d(pa));
    const double len = length(normal);
    if (!(len > 0) || !std::isfinite(len)) continue;
    corners_.insert(corners_.end(), {base + a, base + b, base + c});
    face_normal_.push_back(Vec3f(normal / len));
    smooth_.push_back(uint8_t((has_normals ? kHasNormals : 0) | (has_uv ? kHasParameters : 0)));
    layer_.push_back(layer.value_or(meshes_));
    ++kept;
  }
  // Vertices without normals or uv in a store where other meshes have them: keep the arrays
  // parallel (the flags say which triangles use them).
  if (!N_.empty()) N_.resize(P_.size(), Vec3f{});
  if (!uv_.empty()) uv_.resize(P_.size(), Vec2f{});
  ++meshes_;
  return kept;
}

BBox TriangleStore::bounds(uint32_t triangle) const {
  BBox box;
  for (int k = 0; k < 3; ++k) box.extend(P_[corners_[3 * triangle + k]]);
  const float pad = kBoundsRelativePadding * max_component(max(abs(box.lo), abs(box.hi)));
  return box.expanded(pad);
}

bool TriangleStore::intersect(uint32_t triangle, const Ray& ray, SurfaceHit& hit) const {
  const uint32_t* c = &corners_[3 * size_t(triangle)];
  const Vec3d a(P_[c[0]]), e1 = Vec3d(P_[c[1]]) - a, e2 = Vec3d(P_[c[2]]) - a;
  const Vec3d d(ray.d), o(ray.o);
  const Vec3d pvec = cross(d, e2);
  const double det = dot(e1, pvec);
  if (!(det != 0) || !std::isfinite(det)) return false;  // parallel to the plane (or NaN)
  const double inv = 1.0 / det;
  const Vec3d tvec = o - a;
  const double b1 = dot(tvec, pvec) * inv;
  if (!(b1 >= 0 && b1 <= 1)) return false;
  const Vec3d qvec = cross(tvec, e1);
  const double b2 = dot(d, qvec) * inv;
  if (!(b2 >= 0 && b1 + b2 <= 1)) return false;
  const double t = dot(e2, qvec) * inv;
  if (!(t > double(ray.tmin) && t < double(ray.tmax))) return false;
  hit.t = float(t);
  hit.p = Vec3f(o + d * t);
  hit.ng = face_normal_[triangle];
  if (!uv_.empty()) {
    const Vec2f& ua = uv_[c[0]];
    const Vec2f& ub = uv_[c[1]];
    const Vec2f& uc = uv_[c[2]];
    const float w1 = float(b1), w2 = float(b2), w0 = 1.0f - w1 - w2;
    hit.u = w0 * ua.x + w1 * ub.x + w2 * uc.x;
    hit.v = w0 * ua.y + w1 * ub.y + w2 * uc.y;
  } else {
    hit.u = float(b1);
    hit.v = float(b2);
  }
  return true;
}

Vec2f TriangleStore::plane_coordinates(uint32_t triangle, const Vec3f& w_from_a, bool clamp) const {
  const uint32_t* c = &corners_[3 * size_t(triangle)];
  const Vec3d a(P_[c[0]]), e1 = Vec3d(P_[c[1]]) - a, e2 = Vec3d(P_[c[2]]) - a, w(w_from_a);
  // Least squares in the plane: [e1 e2] (b1, b2) ~ w.
  const double d11 = dot(e1, e1), d12 = dot(e1, e2), d22 = dot(e2, e2);
  const double r1 = dot(w, e1), r2 = dot(w, e2);
  const double det = d11 * d22 - d12 * d12;
  if (!(det > 0)) return {0, 0};
  double b1 = (d22 * r1 - d12 * r2) / det, b2 = (d11 * r2 - d12 * r1) / det;
  if (clamp) {
    b1 = std::clamp(b1, 0.0, 1.0);
    b2 = std::clamp(b2, 0.0, 1.0 - b1);
  }
  return {float(b1), float(b2)};
}

Vec2f TriangleStore::barycentric(uint32_t triangle, const Vec3f& p) const {
  return plane_coordinates(triangle, p - P_[corners_[3 * size_t(triangle)]], true);
}

bool TriangleStore::parameters(uint32_t triangle, const Vec3f& p, const Vec3f& dx, const Vec3f& dy, Vec2f& uv,
                               Vec2f& duv_dx, Vec2f& duv_dy) const {
  if (!(smooth_[triangle] & kHasParameters)) return false;
  const uint32_t* c = &corners_[3 * size_t(triangle)];
  const Vec2f a = uv_[c[0]], b = uv_[c[1]], cc = uv_[c[2]];
  // (u, v) is affine on the plane: its change along a footprint axis is exact, whatever the
  // axis' length (a footprint larger than the triangle extends the triangle's own gradient).
  auto along = [&](const Vec2f& w) {
    return Vec2f{(b.x - a.x) * w.x + (cc.x - a.x) * w.y, (b.y - a.y) * w.x + (cc.y - a.y) * w.y};
  };
  const Vec2f at = along(barycentric(triangle, p));
  uv = {a.x + at.x, a.y + at.y};
  duv_dx = along(plane_coordinates(triangle, dx, false));
  duv_dy = along(plane_coordinates(triangle, dy, false));
  return true;
}

Vec3f TriangleStore::shading_normal(uint32_t triangle, const Vec3f& p) const {
  const Vec3f ng = face_normal_[triangle];
  if (!(smooth_[triangle] & kHasNormals)) return ng;
  const uint32_t* c = &corners_[3 * size_t(triangle)];
  const Vec2f b = barycentric(triangle, p);
  const Vec3f n = N_[c[0]] * (1.0f - b.x - b.y) + N_[c[1]] * b.x + N_[c[2]] * b.y;
  const float len = length(n);
  if (!(len > 0)) return ng;
  const Vec3f unit = n / len;
  // Normals from the limit surface point the face's way; a vertex normal across a fold would not.
  return dot(unit, ng) < 0 ? -unit : unit;
}

size_t TriangleStore::memory_bytes() const {
  return P_.capacity() * sizeof(Vec3f) + N_.capacity() * sizeof(Vec3f) + uv_.capacity() * sizeof(Vec2f) +
         corners_.capacity() * sizeof(uint32_t) + face_normal_.capacity() * sizeof(Vec3f) + smooth_.capacity() +
         layer_.capacity() * sizeof(uint32_t);
}

}  // namespace darc
