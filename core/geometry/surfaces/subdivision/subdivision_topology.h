// The connectivity of a polygon mesh as Catmull-Clark subdivision needs it: faces as corner
// lists, the edges between them with their one or two faces, and the faces around each vertex
// in the order a walk around the vertex meets them. Building it is where non-manifold or
// inconsistently oriented input is found and refused, so the refinement and limit code can
// assume a 2-manifold (with boundary) whose faces all wind the same way.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

namespace darc {

inline constexpr uint32_t kNoFace = UINT32_MAX;

// A corner is one (face, vertex) pair; corners are numbered face by face in face order, so face f
// owns corners face_starts[f] .. face_starts[f + 1].
struct SubdivisionTopology {
  uint32_t vertex_count = 0;
  std::vector<uint32_t> face_starts;                   // face_count() + 1 entries
  std::vector<uint32_t> corner_vertex;                 // the vertex at each corner
  std::vector<uint32_t> corner_face;                   // the face each corner belongs to
  std::vector<uint32_t> corner_edge;                   // the edge from this corner's vertex to the next corner's
  std::vector<std::array<uint32_t, 2>> edge_vertices;  // as the first face to use it runs
  std::vector<std::array<uint32_t, 2>> edge_faces;     // [1] is kNoFace on a boundary edge
  // The corners at each vertex, ordered around it (CSR: vertex v's are
  // vertex_corners[vertex_corner_starts[v] .. vertex_corner_starts[v + 1]]). Corner i + 1 is in
  // the face across the edge from corner i's previous vertex to v. On a boundary vertex the walk
  // starts at the corner whose outgoing edge (v, next) is a boundary edge.
  std::vector<uint32_t> vertex_corner_starts;
  std::vector<uint32_t> vertex_corners;
  std::vector<uint8_t> vertex_on_boundary;

  uint32_t face_count() const { return uint32_t(face_starts.size()) - 1; }
  uint32_t edge_count() const { return uint32_t(edge_vertices.size()); }
  uint32_t face_size(uint32_t f) const { return face_starts[f + 1] - face_starts[f]; }
  bool is_boundary_edge(uint32_t e) const { return edge_faces[e][1] == kNoFace; }
  // The corner after / before c in its face.
  uint32_t next_corner(uint32_t c) const;
  uint32_t previous_corner(uint32_t c) const;
  // The edges at vertex v, in ring order: the outgoing edge of each of its corners, then on a
  // boundary vertex the incoming edge of the last corner (the other boundary edge).
  void vertex_edges(uint32_t v, std::vector<uint32_t>& edges) const;
  // The vertex at the other end of edge e from v.
  uint32_t other_end(uint32_t e, uint32_t v) const {
    return edge_vertices[e][0] == v ? edge_vertices[e][1] : edge_vertices[e][0];
  }
  // The edge between vertices a and b (either order), if there is one.
  std::optional<uint32_t> find_edge(uint32_t a, uint32_t b) const;

  // Builds the topology of faces given as vertex lists (face_sizes[f] vertices each, read in
  // order from face_vertices). Returns nullopt and sets error when a face has fewer than 3
  // vertices or repeats one, a vertex index is out of range, an edge has more than two faces or
  // two faces run it the same way (inconsistent orientation), or the faces around a vertex do not
  // form one fan (a "bowtie" vertex). Vertices no face uses are allowed (they have no corners).
  static std::optional<SubdivisionTopology> build(uint32_t vertex_count, const std::vector<uint32_t>& face_sizes,
                                                  const std::vector<uint32_t>& face_vertices, std::string& error);

 private:
  std::unordered_map<uint64_t, uint32_t> edge_index_;  // key: min vertex << 32 | max vertex
};

}  // namespace darc
