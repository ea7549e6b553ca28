// Measurements of a tessellated mesh that the patch and NURBS tests compare with analytic values:
// area, boundary edges (cracks and closure), winding against the vertex normals, the turn of the
// normals along an edge, and finiteness.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <utility>

#include "core/geometry/surfaces/triangle_mesh_data.h"

namespace darc::test {

inline Vec3d vertex(const TriangleMeshData& m, uint32_t i) { return Vec3d(m.P[i]); }

inline double mesh_area(const TriangleMeshData& m) {
  double area = 0;
  for (size_t t = 0; t < m.indices.size(); t += 3) {
    const Vec3d a = vertex(m, m.indices[t]), b = vertex(m, m.indices[t + 1]), c = vertex(m, m.indices[t + 2]);
    area += 0.5 * length(cross(b - a, c - a));
  }
  return area;
}

// How many triangles use each undirected edge (by vertex index).
inline std::map<std::pair<uint32_t, uint32_t>, int> edge_uses(const TriangleMeshData& m) {
  std::map<std::pair<uint32_t, uint32_t>, int> uses;
  for (size_t t = 0; t < m.indices.size(); t += 3)
    for (int e = 0; e < 3; ++e) {
      uint32_t a = m.indices[t + size_t(e)], b = m.indices[t + size_t((e + 1) % 3)];
      ++uses[{std::min(a, b), std::max(a, b)}];
    }
  return uses;
}

// Edges used by one triangle only (the surface's border; a crack would add to them).
inline int boundary_edges(const TriangleMeshData& m) {
  int n = 0;
  for (const auto& [edge, count] : edge_uses(m)) n += count == 1;
  return n;
}

// Edges used by more than two triangles (never, for a grid).
inline int non_manifold_edges(const TriangleMeshData& m) {
  int n = 0;
  for (const auto& [edge, count] : edge_uses(m)) n += count > 2;
  return n;
}

// Triangles of nonzero area whose right-hand normal points away from their vertex normals.
inline int wound_against_normals(const TriangleMeshData& m) {
  int n = 0;
  for (size_t t = 0; t < m.indices.size(); t += 3) {
    const uint32_t ia = m.indices[t], ib = m.indices[t + 1], ic = m.indices[t + 2];
    const Vec3d face = cross(vertex(m, ib) - vertex(m, ia), vertex(m, ic) - vertex(m, ia));
    const Vec3d normals = Vec3d(m.N[ia]) + Vec3d(m.N[ib]) + Vec3d(m.N[ic]);
    if (length(face) > 1e-12 && dot(face, normals) <= 0) ++n;
  }
  return n;
}

// The largest angle (radians) between the normals at the two ends of an edge.
inline double max_normal_turn(const TriangleMeshData& m) {
  double turn = 0;
  for (const auto& [edge, count] : edge_uses(m)) {
    const Vec3d a = Vec3d(m.N[edge.first]), b = Vec3d(m.N[edge.second]);
    turn = std::max(turn, std::atan2(length(cross(a, b)), dot(a, b)));
  }
  return turn;
}

// Every position, normal and uv finite, every normal of unit length, every index in range.
inline bool well_formed(const TriangleMeshData& m) {
  if (m.N.size() != m.P.size() || m.uv.size() != m.P.size() || m.indices.size() % 3 != 0) return false;
  for (size_t i = 0; i < m.P.size(); ++i) {
    const Vec3f p = m.P[i], n = m.N[i];
    if (!(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z))) return false;
    if (!(std::isfinite(m.uv[i].x) && std::isfinite(m.uv[i].y))) return false;
    if (!(std::abs(length(n) - 1) < 1e-5f)) return false;
  }
  for (uint32_t i : m.indices)
    if (i >= m.P.size()) return false;
  return true;
}

}  // namespace darc::test
