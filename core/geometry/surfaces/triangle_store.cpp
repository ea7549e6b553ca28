#include "core/geometry/surfaces/triangle_store.h"

#include "core/math/motion_keys.h"

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
  if (!vertex_motion_.empty()) vertex_motion_.resize(P_.size(), kStaticVertex);
  ++meshes_;
  return kept;
}

size_t TriangleStore::add_moving(std::span<const float> times, std::span<const TriangleMeshData> keys,
                                std::optional<uint32_t> layer) {
  if (keys.empty()) return 0;
  const TriangleMeshData& first = keys.front();
  const size_t n = first.P.size();
  const bool still = std::all_of(keys.begin(), keys.end(), [&](const TriangleMeshData& k) {
    return k.P.size() == n && std::equal(k.P.begin(), k.P.end(), first.P.begin(), [](const Vec3f& a, const Vec3f& b) {
             return a.x == b.x && a.y == b.y && a.z == b.z;
           });
  });
  if (still || times.size() != keys.size()) return add(first, layer);
  // Triangles with a corner beyond the float range at any key are dropped here; add() drops the
  // ones that are degenerate or non-finite at shutter open.
  TriangleMeshData kept = first;
  kept.indices.clear();
  for (size_t t = 0; t + 2 < first.indices.size(); t += 3) {
    bool finite_everywhere = true;
    for (const TriangleMeshData& key : keys)
      for (size_t k = 0; k < 3; ++k) {
        const uint32_t v = first.indices[t + k];
        finite_everywhere = finite_everywhere && v < n && key.P.size() == n && finite(key.P[v]);
      }
    if (finite_everywhere) kept.indices.insert(kept.indices.end(), first.indices.begin() + long(t), first.indices.begin() + long(t + 3));
  }
  const uint32_t base = uint32_t(P_.size());
  const size_t added = add(kept, layer);
  MeshMotion motion;
  motion.times = uint32_t(motion_times_.size());
  motion.keys = uint32_t(keys.size());
  motion.first_vertex = base;
  motion.count = uint32_t(n);
  motion.positions = motion_P_.size();
  motion.normals = first.N.size() == n;
  motion_times_.insert(motion_times_.end(), times.begin(), times.end());
  for (const TriangleMeshData& key : keys) motion_P_.insert(motion_P_.end(), key.P.begin(), key.P.end());
  if (motion.normals) {
    motion_N_.resize(motion.positions, Vec3f{});
    for (const TriangleMeshData& key : keys) {
      if (key.N.size() == n) {
        motion_N_.insert(motion_N_.end(), key.N.begin(), key.N.end());
      } else {
        motion_N_.insert(motion_N_.end(), first.N.begin(), first.N.end());
      }
    }
  }
  vertex_motion_.resize(base, kStaticVertex);
  vertex_motion_.resize(P_.size(), uint32_t(motions_.size()));
  motions_.push_back(motion);
  return added;
}

bool TriangleStore::moving(uint32_t triangle) const {
  if (vertex_motion_.empty()) return false;
  const uint32_t* c = &corners_[3 * size_t(triangle)];
  return vertex_motion_[c[0]] != kStaticVertex || vertex_motion_[c[1]] != kStaticVertex ||
         vertex_motion_[c[2]] != kStaticVertex;
}

Vec3f TriangleStore::vertex_at(uint32_t v, float time) const {
  if (vertex_motion_.empty() || vertex_motion_[v] == kStaticVertex) return P_[v];
  const MeshMotion& m = motions_[vertex_motion_[v]];
  uint32_t k;
  float s;
  key_interval(&motion_times_[m.times], m.keys, time, k, s);
  const size_t i = m.positions + size_t(k) * m.count + (v - m.first_vertex);
  const Vec3f& a = motion_P_[i];
  const Vec3f& b = motion_P_[i + m.count];
  return s == 0.0f ? a : s == 1.0f ? b : a + (b - a) * s;
}

Vec3f TriangleStore::normal_at(uint32_t v, float time) const {
  if (vertex_motion_.empty() || vertex_motion_[v] == kStaticVertex) return N_[v];
  const MeshMotion& m = motions_[vertex_motion_[v]];
  if (!m.normals) return N_[v];
  uint32_t k;
  float s;
  key_interval(&motion_times_[m.times], m.keys, time, k, s);
  const size_t i = m.positions + size_t(k) * m.count + (v - m.first_vertex);
  const Vec3f n = motion_N_[i] + (motion_N_[i + m.count] - motion_N_[i]) * s;
  const float len = length(n);
  return len > 0 ? n / len : motion_N_[i];
}

Vec3f TriangleStore::face_normal(uint32_t triangle, float time) const {
  if (!moving(triangle)) return face_normal_[triangle];
  const Vec3d a(corner(triangle, 0, time));
  const Vec3d normal = cross(Vec3d(corner(triangle, 1, time)) - a, Vec3d(corner(triangle, 2, time)) - a);
  const double len = length(normal);
  // Degenerate at this time (a triangle that collapses mid-shutter): the normal at open.
  return len > 0 && std::isfinite(len) ? Vec3f(normal / len) : face_normal_[triangle];
}

BBox TriangleStore::bounds(uint32_t triangle) const {
  BBox box;
  for (int k = 0; k < 3; ++k) box.extend(P_[corners_[3 * triangle + k]]);
  if (moving(triangle)) {
    // Vertices move linearly between keys: the keys' corners bound the whole shutter.
    for (int k = 0; k < 3; ++k) {
      const uint32_t v = corners_[3 * triangle + k];
      if (vertex_motion_[v] == kStaticVertex) continue;
      const MeshMotion& m = motions_[vertex_motion_[v]];
      for (uint32_t key = 0; key < m.keys; ++key)
        box.extend(motion_P_[m.positions + size_t(key) * m.count + (v - m.first_vertex)]);
    }
  }
  const float pad = kBoundsRelativePadding * max_component(max(abs(box.lo), abs(box.hi)));
  return box.expanded(pad);
}

bool TriangleStore::intersect(uint32_t triangle, const Ray& ray, SurfaceHit& hit) const {
  const uint32_t* c = &corners_[3 * size_t(triangle)];
  const bool moves = moving(triangle);
  const Vec3d a(moves ? vertex_at(c[0], ray.time) : P_[c[0]]);
  const Vec3d e1 = Vec3d(moves ? vertex_at(c[1], ray.time) : P_[c[1]]) - a;
  const Vec3d e2 = Vec3d(moves ? vertex_at(c[2], ray.time) : P_[c[2]]) - a;
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
  hit.ng = moves ? face_normal(triangle, ray.time) : face_normal_[triangle];
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

Vec2f TriangleStore::plane_coordinates(uint32_t triangle, const Vec3f& w_from_a, bool clamp, float time) const {
  const Vec3d a(corner(triangle, 0, time)), e1 = Vec3d(corner(triangle, 1, time)) - a,
      e2 = Vec3d(corner(triangle, 2, time)) - a, w(w_from_a);
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

Vec2f TriangleStore::barycentric(uint32_t triangle, const Vec3f& p, float time) const {
  return plane_coordinates(triangle, p - corner(triangle, 0, time), true, time);
}

bool TriangleStore::parameters(uint32_t triangle, const Vec3f& p, const Vec3f& dx, const Vec3f& dy, Vec2f& uv,
                               Vec2f& duv_dx, Vec2f& duv_dy, float time) const {
  if (!(smooth_[triangle] & kHasParameters)) return false;
  const uint32_t* c = &corners_[3 * size_t(triangle)];
  const Vec2f a = uv_[c[0]], b = uv_[c[1]], cc = uv_[c[2]];
  // (u, v) is affine on the plane: its change along a footprint axis is exact, whatever the
  // axis' length (a footprint larger than the triangle extends the triangle's own gradient).
  auto along = [&](const Vec2f& w) {
    return Vec2f{(b.x - a.x) * w.x + (cc.x - a.x) * w.y, (b.y - a.y) * w.x + (cc.y - a.y) * w.y};
  };
  const Vec2f at = along(barycentric(triangle, p, time));
  uv = {a.x + at.x, a.y + at.y};
  duv_dx = along(plane_coordinates(triangle, dx, false, time));
  duv_dy = along(plane_coordinates(triangle, dy, false, time));
  return true;
}

Vec3f TriangleStore::shading_normal(uint32_t triangle, const Vec3f& p, float time) const {
  const Vec3f ng = face_normal(triangle, time);
  if (!(smooth_[triangle] & kHasNormals)) return ng;
  const uint32_t* c = &corners_[3 * size_t(triangle)];
  const Vec2f b = barycentric(triangle, p, time);
  const Vec3f n = normal_at(c[0], time) * (1.0f - b.x - b.y) + normal_at(c[1], time) * b.x + normal_at(c[2], time) * b.y;
  const float len = length(n);
  if (!(len > 0)) return ng;
  const Vec3f unit = n / len;
  // Normals from the limit surface point the face's way; a vertex normal across a fold would not.
  return dot(unit, ng) < 0 ? -unit : unit;
}

size_t TriangleStore::memory_bytes() const {
  return P_.capacity() * sizeof(Vec3f) + N_.capacity() * sizeof(Vec3f) + uv_.capacity() * sizeof(Vec2f) +
         corners_.capacity() * sizeof(uint32_t) + face_normal_.capacity() * sizeof(Vec3f) + smooth_.capacity() +
         layer_.capacity() * sizeof(uint32_t) + vertex_motion_.capacity() * sizeof(uint32_t) +
         motions_.capacity() * sizeof(MeshMotion) + motion_times_.capacity() * sizeof(float) +
         (motion_P_.capacity() + motion_N_.capacity()) * sizeof(Vec3f);
}

}  // namespace darc
