#include "core/geometry/surfaces/subdivision/catmull_clark_limit.h"

#include <cmath>
#include <numbers>
#include <unordered_map>

namespace darc {

namespace {

// What the limit code needs to know about one vertex of the final level.
struct LimitVertex {
  VertexRule rule = VertexRule::Smooth;
  uint32_t sector_count = 1;
  uint32_t first_output_slot = 0;  // slots[first_output_slot + sector] holds the emitted index
};

int sharp_edge_count(const SubdivisionLevel& level, const std::vector<uint32_t>& edges, uint32_t far_end[2],
                     uint32_t v) {
  int count = 0;
  for (uint32_t e : edges) {
    if (level.edge_sharpness[e] <= 0.0f) continue;
    if (count < 2) far_end[count] = level.topology.other_end(e, v);
    ++count;
  }
  return count;
}

Vec3d smooth_limit_position(const SubdivisionLevel& level, const std::vector<Vec3d>& x, uint32_t v) {
  const SubdivisionTopology& t = level.topology;
  uint32_t begin = t.vertex_corner_starts[v], end = t.vertex_corner_starts[v + 1];
  double n = double(end - begin);
  Vec3d edge_sum, face_sum;
  for (uint32_t i = begin; i < end; ++i) {
    uint32_t c = t.vertex_corners[i];
    uint32_t next = t.next_corner(c);
    edge_sum += x[t.corner_vertex[next]];
    face_sum += x[t.corner_vertex[t.next_corner(next)]];
  }
  return (x[v] * (n * n) + edge_sum * 4.0 + face_sum) / (n * (n + 5.0));
}

// The limit of a quantity x given per vertex and subdivided by the level's rules (positions, or
// vertex-class texture coordinates) at vertex v, which moves by `rule`.
Vec3d limit_value(const SubdivisionLevel& level, const std::vector<Vec3d>& x, uint32_t v, VertexRule rule,
                  const uint32_t far_end[2]) {
  switch (rule) {
    case VertexRule::Corner:
      return x[v];
    case VertexRule::Crease:
      return (x[far_end[0]] + x[v] * 4.0 + x[far_end[1]]) / 6.0;
    case VertexRule::Smooth:
      break;
  }
  return smooth_limit_position(level, x, v);
}

// The limit normal of a smooth (interior) vertex from the two tangent masks; it points the way
// of its faces' right-hand normals because e_0 -> e_1 turns as the faces do.
Vec3d smooth_limit_normal(const SubdivisionLevel& level, uint32_t v) {
  const SubdivisionTopology& t = level.topology;
  uint32_t begin = t.vertex_corner_starts[v], end = t.vertex_corner_starts[v + 1];
  uint32_t n = end - begin;
  double step = 2.0 * std::numbers::pi / double(n);
  double a = 1.0 + std::cos(step) + std::cos(step / 2.0) * std::sqrt(2.0 * (9.0 + std::cos(step)));
  Vec3d t1, t2;
  for (uint32_t i = 0; i < n; ++i) {
    uint32_t c = t.vertex_corners[begin + i];
    uint32_t next = t.next_corner(c);
    const Vec3d& e = level.points[t.corner_vertex[next]];
    const Vec3d& f = level.points[t.corner_vertex[t.next_corner(next)]];
    double angle = step * double(i);
    t1 += e * (a * std::cos(angle)) + f * (std::cos(angle) + std::cos(angle + step));
    t2 += e * (a * std::sin(angle)) + f * (std::sin(angle) + std::sin(angle + step));
  }
  return cross(t1, t2);
}

// Sector of each of v's corners (in ring order): a new sector starts at a corner whose outgoing
// edge is sharp. Returns the number of sectors.
uint32_t assign_sectors(const SubdivisionLevel& level, uint32_t v, std::vector<uint32_t>& corner_sector) {
  const SubdivisionTopology& t = level.topology;
  uint32_t begin = t.vertex_corner_starts[v], end = t.vertex_corner_starts[v + 1];
  uint32_t n = end - begin;
  auto sharp_before = [&](uint32_t i) { return level.edge_sharpness[t.corner_edge[t.vertex_corners[begin + i]]] > 0; };
  uint32_t first = 0;
  while (first < n && !sharp_before(first)) ++first;
  if (first == n) first = 0;  // no sharp edge between faces: one sector
  uint32_t sector = 0;
  for (uint32_t k = 0; k < n; ++k) {
    uint32_t i = (first + k) % n;
    if (k > 0 && sharp_before(i)) ++sector;
    corner_sector[t.vertex_corners[begin + i]] = sector;
  }
  return sector + 1;
}

// Area-weighted normal of v's limit faces in one sector.
Vec3d sector_normal(const SubdivisionTopology& t, const std::vector<Vec3d>& limit, uint32_t v, uint32_t sector,
                    const std::vector<uint32_t>& corner_sector) {
  Vec3d sum;
  for (uint32_t i = t.vertex_corner_starts[v]; i < t.vertex_corner_starts[v + 1]; ++i) {
    uint32_t c = t.vertex_corners[i];
    if (corner_sector[c] != sector) continue;
    const Vec3d& next = limit[t.corner_vertex[t.next_corner(c)]];
    const Vec3d& previous = limit[t.corner_vertex[t.previous_corner(c)]];
    sum += cross(next - limit[v], previous - limit[v]);
  }
  return sum;
}

}  // namespace

void append_limit_triangles(const SubdivisionLevel& level, TriangleMeshData& mesh,
                            std::vector<uint32_t>& triangle_control_face) {
  const SubdivisionTopology& t = level.topology;
  const uint32_t nv = t.vertex_count;
  std::vector<LimitVertex> vertices(nv);
  std::vector<Vec3d> limit(nv);
  std::vector<Vec3d> limit_st(level.vertex_st.empty() ? 0 : nv);
  std::vector<uint32_t> corner_sector(t.corner_vertex.size(), 0);
  std::vector<uint32_t> edges;
  uint32_t slot_count = 0;
  for (uint32_t v = 0; v < nv; ++v) {
    LimitVertex& lv = vertices[v];
    t.vertex_edges(v, edges);
    uint32_t far_end[2] = {0, 0};
    lv.rule = vertex_rule(sharp_edge_count(level, edges, far_end, v), level.vertex_sharpness[v]);
    if (edges.empty()) lv.rule = VertexRule::Corner;  // a vertex no face uses
    limit[v] = limit_value(level, level.points, v, lv.rule, far_end);
    if (!limit_st.empty()) limit_st[v] = limit_value(level, level.vertex_st, v, lv.rule, far_end);
    lv.sector_count = lv.rule == VertexRule::Smooth ? 1 : assign_sectors(level, v, corner_sector);
    lv.first_output_slot = slot_count;
    slot_count += lv.sector_count;
  }

  // The texture coordinates of corner c: per-corner values are their own limit (they are
  // refined linearly).
  const bool has_st = !limit_st.empty() || !level.corner_st.empty();
  auto corner_st = [&](uint32_t c) {
    const Vec3d st = level.corner_st.empty() ? limit_st[t.corner_vertex[c]] : level.corner_st[c];
    return Vec2f{float(st.x), float(st.y)};
  };
  std::vector<uint32_t> slots(slot_count, UINT32_MAX);
  // Where per-corner texture coordinates differ between the corners of one slot (a seam of the
  // st map), the slot's vertex is emitted once per distinct value: the slot keeps the first,
  // seam_copies the others.
  std::unordered_multimap<uint32_t, uint32_t> seam_copies;
  auto emitted_vertex = [&](uint32_t c) {
    uint32_t v = t.corner_vertex[c];
    const uint32_t slot_index = vertices[v].first_output_slot + corner_sector[c];
    uint32_t& slot = slots[slot_index];
    const Vec2f st = has_st ? corner_st(c) : Vec2f{};
    auto same_st = [&](uint32_t emitted) { return mesh.uv[emitted].x == st.x && mesh.uv[emitted].y == st.y; };
    if (slot != UINT32_MAX) {
      if (!has_st || same_st(slot)) return slot;
      const auto [first, last] = seam_copies.equal_range(slot_index);
      for (auto it = first; it != last; ++it) {
        if (same_st(it->second)) return it->second;
      }
    }
    Vec3d normal = vertices[v].rule == VertexRule::Smooth ? smooth_limit_normal(level, v)
                                                          : sector_normal(t, limit, v, corner_sector[c], corner_sector);
    // A degenerate neighbourhood (coincident control points) has no tangent plane from the
    // masks; the faces' normal, then +z, keep N a unit vector.
    if (length_squared(normal) == 0.0) normal = sector_normal(t, limit, v, corner_sector[c], corner_sector);
    if (length_squared(normal) == 0.0) normal = {0, 0, 1};
    const uint32_t emitted = uint32_t(mesh.P.size());
    mesh.P.push_back(Vec3f(limit[v]));
    mesh.N.push_back(Vec3f(normalize(normal)));
    if (has_st) mesh.uv.push_back(st);
    if (slot == UINT32_MAX) slot = emitted;
    else seam_copies.emplace(slot_index, emitted);
    return emitted;
  };

  for (uint32_t f = 0; f < t.face_count(); ++f) {
    if (level.face_hidden[f]) continue;
    uint32_t c0 = t.face_starts[f];
    uint32_t q[4] = {emitted_vertex(c0), emitted_vertex(c0 + 1), emitted_vertex(c0 + 2), emitted_vertex(c0 + 3)};
    mesh.indices.insert(mesh.indices.end(), {q[0], q[1], q[2], q[0], q[2], q[3]});
    triangle_control_face.push_back(level.face_control_face[f]);
    triangle_control_face.push_back(level.face_control_face[f]);
  }
}

}  // namespace darc
