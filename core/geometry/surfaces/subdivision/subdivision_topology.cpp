#include "core/geometry/surfaces/subdivision/subdivision_topology.h"

#include <fmt/format.h>

#include <algorithm>

namespace darc {

namespace {

uint64_t edge_key(uint32_t a, uint32_t b) { return (uint64_t(std::min(a, b)) << 32) | uint64_t(std::max(a, b)); }

// The corner of vertex v in face f (the face is known to contain v).
uint32_t corner_of_vertex_in_face(const SubdivisionTopology& t, uint32_t f, uint32_t v) {
  for (uint32_t c = t.face_starts[f]; c < t.face_starts[f + 1]; ++c) {
    if (t.corner_vertex[c] == v) return c;
  }
  return UINT32_MAX;  // unreachable for a face that contains v
}

// The corner at the same vertex in the face across edge e from corner c's face, or UINT32_MAX.
uint32_t corner_across(const SubdivisionTopology& t, uint32_t c, uint32_t e) {
  uint32_t f = t.corner_face[c];
  uint32_t g = t.edge_faces[e][0] == f ? t.edge_faces[e][1] : t.edge_faces[e][0];
  return g == kNoFace ? UINT32_MAX : corner_of_vertex_in_face(t, g, t.corner_vertex[c]);
}

}  // namespace

uint32_t SubdivisionTopology::next_corner(uint32_t c) const {
  uint32_t f = corner_face[c];
  return c + 1 == face_starts[f + 1] ? face_starts[f] : c + 1;
}

uint32_t SubdivisionTopology::previous_corner(uint32_t c) const {
  uint32_t f = corner_face[c];
  return c == face_starts[f] ? face_starts[f + 1] - 1 : c - 1;
}

void SubdivisionTopology::vertex_edges(uint32_t v, std::vector<uint32_t>& edges) const {
  edges.clear();
  uint32_t begin = vertex_corner_starts[v], end = vertex_corner_starts[v + 1];
  for (uint32_t i = begin; i < end; ++i) edges.push_back(corner_edge[vertex_corners[i]]);
  if (vertex_on_boundary[v] && begin < end) edges.push_back(corner_edge[previous_corner(vertex_corners[end - 1])]);
}

std::optional<uint32_t> SubdivisionTopology::find_edge(uint32_t a, uint32_t b) const {
  auto it = edge_index_.find(edge_key(a, b));
  if (it == edge_index_.end()) return std::nullopt;
  return it->second;
}

std::optional<SubdivisionTopology> SubdivisionTopology::build(uint32_t vertex_count,
                                                              const std::vector<uint32_t>& face_sizes,
                                                              const std::vector<uint32_t>& face_vertices,
                                                              std::string& error) {
  SubdivisionTopology t;
  t.vertex_count = vertex_count;
  t.face_starts.reserve(face_sizes.size() + 1);
  t.face_starts.push_back(0);
  for (uint32_t f = 0; f < face_sizes.size(); ++f) {
    uint32_t start = t.face_starts.back();
    if (face_sizes[f] < 3) {
      error = fmt::format("face {} has {} vertices (a face needs at least 3)", f, face_sizes[f]);
      return std::nullopt;
    }
    if (start + uint64_t(face_sizes[f]) > face_vertices.size()) {
      error = fmt::format("face {} runs past the end of the vertex list", f);
      return std::nullopt;
    }
    for (uint32_t k = 0; k < face_sizes[f]; ++k) {
      uint32_t v = face_vertices[start + k];
      if (v >= vertex_count) {
        error = fmt::format("face {} uses vertex {}, but there are {} vertices", f, v, vertex_count);
        return std::nullopt;
      }
      for (uint32_t j = 0; j < k; ++j) {
        if (face_vertices[start + j] == v) {
          error = fmt::format("face {} uses vertex {} twice", f, v);
          return std::nullopt;
        }
      }
      t.corner_vertex.push_back(v);
      t.corner_face.push_back(f);
    }
    t.face_starts.push_back(start + face_sizes[f]);
  }

  // Edges: the first face to run an edge fixes its direction; a second face must run it the
  // other way, and there is no third.
  t.corner_edge.resize(t.corner_vertex.size());
  t.edge_index_.reserve(t.corner_vertex.size());
  for (uint32_t c = 0; c < t.corner_vertex.size(); ++c) {
    uint32_t a = t.corner_vertex[c];
    uint32_t b = t.corner_vertex[t.next_corner(c)];
    uint32_t f = t.corner_face[c];
    auto [it, inserted] = t.edge_index_.try_emplace(edge_key(a, b), t.edge_count());
    if (inserted) {
      t.edge_vertices.push_back({a, b});
      t.edge_faces.push_back({f, kNoFace});
    } else {
      uint32_t e = it->second;
      if (t.edge_faces[e][1] != kNoFace) {
        error = fmt::format("edge ({}, {}) has more than two faces ({}, {}, {}): the mesh is not a manifold", a, b,
                            t.edge_faces[e][0], t.edge_faces[e][1], f);
        return std::nullopt;
      }
      if (t.edge_vertices[e][0] == a) {
        error =
            fmt::format("faces {} and {} both run edge ({}, {}) from {} to {}: the faces are not consistently oriented",
                        t.edge_faces[e][0], f, a, b, a, b);
        return std::nullopt;
      }
      t.edge_faces[e][1] = f;
    }
    t.corner_edge[c] = it->second;
  }

  // Corners by vertex, then each vertex's corners put in order around it.
  t.vertex_corner_starts.assign(vertex_count + 1, 0);
  for (uint32_t v : t.corner_vertex) ++t.vertex_corner_starts[v + 1];
  for (uint32_t v = 0; v < vertex_count; ++v) t.vertex_corner_starts[v + 1] += t.vertex_corner_starts[v];
  std::vector<uint32_t> unordered(t.corner_vertex.size());
  {
    std::vector<uint32_t> fill(t.vertex_corner_starts.begin(), t.vertex_corner_starts.end() - 1);
    for (uint32_t c = 0; c < t.corner_vertex.size(); ++c) unordered[fill[t.corner_vertex[c]]++] = c;
  }
  t.vertex_corners.resize(t.corner_vertex.size());
  t.vertex_on_boundary.assign(vertex_count, 0);
  for (uint32_t v = 0; v < vertex_count; ++v) {
    uint32_t begin = t.vertex_corner_starts[v], end = t.vertex_corner_starts[v + 1];
    if (begin == end) continue;
    // A corner with no predecessor has a boundary edge leaving it; a fan has at most one.
    uint32_t start = unordered[begin];
    int open_ends = 0;
    for (uint32_t i = begin; i < end; ++i) {
      uint32_t c = unordered[i];
      if (t.is_boundary_edge(t.corner_edge[c])) {
        if (open_ends++ == 0) start = c;
      }
    }
    t.vertex_on_boundary[v] = open_ends > 0;
    uint32_t count = 0;
    for (uint32_t c = start; c != UINT32_MAX && count < end - begin;) {
      t.vertex_corners[begin + count++] = c;
      uint32_t next = corner_across(t, c, t.corner_edge[t.previous_corner(c)]);
      if (next == start) break;
      c = next;
    }
    if (open_ends > 1 || count != end - begin) {
      error = fmt::format("the faces around vertex {} do not form a single fan (a non-manifold vertex)", v);
      return std::nullopt;
    }
  }
  return t;
}

}  // namespace darc
