#include "core/geometry/surfaces/subdivision/subdivision_surface.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <optional>

#include "core/geometry/surfaces/subdivision/catmull_clark_limit.h"
#include "core/geometry/surfaces/subdivision/catmull_clark_refinement.h"
#include "core/geometry/surfaces/subdivision/subdivision_tags.h"

namespace darc {

namespace {

// Counts and indices; on success face_sizes and face_vertices hold them as unsigned values.
bool check_faces(const SubdivisionMeshRequest& r, std::vector<uint32_t>& face_sizes,
                 std::vector<uint32_t>& face_vertices, std::string& error) {
  if (r.nvertices.empty()) {
    error = "the mesh has no faces (nvertices is empty)";
    return false;
  }
  size_t total = 0;
  for (size_t f = 0; f < r.nvertices.size(); ++f) {
    if (r.nvertices[f] < 3) {
      error = fmt::format("nvertices[{}] is {}: a face needs at least 3 vertices", f, r.nvertices[f]);
      return false;
    }
    total += size_t(r.nvertices[f]);
    face_sizes.push_back(uint32_t(r.nvertices[f]));
  }
  if (total != r.vertices.size()) {
    error = fmt::format("nvertices adds up to {} but vertices has {} indices", total, r.vertices.size());
    return false;
  }
  for (int v : r.vertices) {
    if (v < 0 || size_t(v) >= r.P.size()) {
      error = fmt::format("vertex index {} is out of range: \"P\" has {} points", v, r.P.size());
      return false;
    }
    face_vertices.push_back(uint32_t(v));
  }
  for (const Vec3f& p : r.P) {
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) {
      error = "\"P\" has a non-finite coordinate";
      return false;
    }
  }
  return true;
}

// The control level: points, sharpness from the tags and the boundary rule, hidden faces.
bool make_control_level(const SubdivisionMeshRequest& r, SubdivisionTopology topology, const SubdivisionTags& tags,
                        SubdivisionLevel& level, std::vector<std::string>& warnings) {
  const uint32_t nv = topology.vertex_count, nf = topology.face_count();
  level.points.reserve(nv);
  for (const Vec3f& p : r.P) level.points.push_back(Vec3d(p));
  for (const Vec2f& st : r.vertex_st) level.vertex_st.push_back({st.x, st.y, 0.0});
  for (const Vec2f& st : r.corner_st) level.corner_st.push_back({st.x, st.y, 0.0});
  level.edge_sharpness.assign(topology.edge_count(), 0.0f);
  level.vertex_sharpness.assign(nv, 0.0f);
  level.face_hidden.assign(nf, 0);
  level.face_control_face.resize(nf);
  for (uint32_t f = 0; f < nf; ++f) level.face_control_face[f] = f;

  for (const SubdivisionCreaseEdge& c : tags.crease_edges) {
    std::optional<uint32_t> e = topology.find_edge(c.a, c.b);
    if (!e) {
      warnings.push_back(fmt::format("tag \"crease\": ({}, {}) is not an edge of the mesh: ignored", c.a, c.b));
      continue;
    }
    level.edge_sharpness[*e] = std::max(level.edge_sharpness[*e], c.sharpness);
  }
  for (const SubdivisionCorner& c : tags.corners) {
    level.vertex_sharpness[c.vertex] = std::max(level.vertex_sharpness[c.vertex], c.sharpness);
  }
  for (uint32_t f : tags.hole_faces) level.face_hidden[f] = 1;

  // Refinement treats every boundary edge as a sharp crease; without boundary interpolation the
  // faces whose limit surface would need the missing ring are hidden instead of drawn.
  for (uint32_t e = 0; e < topology.edge_count(); ++e) {
    if (topology.is_boundary_edge(e)) level.edge_sharpness[e] = kInfiniteSharpness;
  }
  for (uint32_t v = 0; v < nv; ++v) {
    if (!topology.vertex_on_boundary[v]) continue;
    uint32_t begin = topology.vertex_corner_starts[v], end = topology.vertex_corner_starts[v + 1];
    if (tags.boundary == BoundaryInterpolation::EdgesAndCorners && end - begin == 1) {
      level.vertex_sharpness[v] = kInfiniteSharpness;
    }
    if (tags.boundary == BoundaryInterpolation::None) {
      for (uint32_t i = begin; i < end; ++i) level.face_hidden[topology.corner_face[topology.vertex_corners[i]]] = 1;
    }
  }
  level.topology = std::move(topology);
  return std::find(level.face_hidden.begin(), level.face_hidden.end(), 0) != level.face_hidden.end();
}

// "bilinear": the control faces themselves, fanned around their first vertex, flat shaded. With
// per-corner texture coordinates each face gets its own vertices (a face's st need not match its
// neighbour's at a shared vertex).
void append_control_faces(const SubdivisionLevel& level, SubdivisionTessellation& out) {
  const SubdivisionTopology& t = level.topology;
  const bool per_corner = !level.corner_st.empty();
  auto st = [](const Vec3d& v) { return Vec2f{float(v.x), float(v.y)}; };
  if (!per_corner) {
    for (const Vec3d& p : level.points) out.mesh.P.push_back(Vec3f(p));
    for (const Vec3d& v : level.vertex_st) out.mesh.uv.push_back(st(v));
  }
  for (uint32_t f = 0; f < t.face_count(); ++f) {
    if (level.face_hidden[f]) continue;
    uint32_t c0 = t.face_starts[f];
    auto vertex = [&](uint32_t c) {
      if (!per_corner) return t.corner_vertex[c];
      out.mesh.P.push_back(Vec3f(level.points[t.corner_vertex[c]]));
      out.mesh.uv.push_back(st(level.corner_st[c]));
      return uint32_t(out.mesh.P.size() - 1);
    };
    const uint32_t first = vertex(c0);
    uint32_t previous = vertex(c0 + 1);
    for (uint32_t c = c0 + 1; c + 1 < t.face_starts[f + 1]; ++c) {
      const uint32_t next = vertex(c + 1);
      out.mesh.indices.insert(out.mesh.indices.end(), {first, previous, next});
      out.triangle_control_face.push_back(f);
      previous = next;
    }
  }
}

}  // namespace

int subdivision_levels_for(size_t control_corner_count) {
  int levels = kMaxSubdivisionLevels;
  // Level L has corners * 4^(L-1) quads, two triangles each.
  while (levels > 1 && 2 * control_corner_count * (size_t(1) << (2 * (levels - 1))) > kSubdivisionTriangleBudget) {
    --levels;
  }
  return levels;
}

int subdivision_levels_on_screen(double longest_edge_pixels, int levels_for_size) {
  int levels = 1;
  while (levels < levels_for_size && longest_edge_pixels / double(1 << levels) > kSubdivisionFacetPixels) ++levels;
  return levels;
}

SubdivisionTessellation tessellate_subdivision_mesh(const SubdivisionMeshRequest& request, const DicingView* view) {
  SubdivisionTessellation out;
  bool bilinear = request.scheme == "bilinear";
  if (request.scheme == "loop") {
    out.warnings.push_back("scheme \"loop\" is not supported: the mesh is refined with the Catmull-Clark rules");
  } else if (request.scheme != "catmull-clark" && !bilinear) {
    out.error = fmt::format("unknown subdivision scheme \"{}\" (expected \"catmull-clark\", \"bilinear\" or \"loop\")",
                            request.scheme);
    return out;
  }
  std::vector<uint32_t> face_sizes, face_vertices;
  if (!check_faces(request, face_sizes, face_vertices, out.error)) return out;
  SubdivisionTags tags;
  if (!read_subdivision_tags(request, uint32_t(request.P.size()), uint32_t(face_sizes.size()), tags, out.warnings,
                             out.error)) {
    return out;
  }
  std::optional<SubdivisionTopology> topology =
      SubdivisionTopology::build(uint32_t(request.P.size()), face_sizes, face_vertices, out.error);
  if (!topology) return out;

  if (bilinear) tags.boundary = BoundaryInterpolation::EdgesAndCorners;  // the faces are drawn as they are
  SubdivisionLevel level;
  if (!make_control_level(request, std::move(*topology), tags, level, out.warnings)) {
    out.warnings.push_back(
        "every face is a hole or touches a boundary that is not interpolated (no \"interpolateboundary\" tag): "
        "nothing to draw");
    return out;
  }
  if (bilinear) {
    append_control_faces(level, out);
    return out;
  }
  out.levels = subdivision_levels_for(face_vertices.size());
  if (view) {
    // The longest control edge in pixels, each measured at the nearer end's pixel size.
    double longest = 0;
    size_t first = 0;
    for (uint32_t n : face_sizes) {
      for (uint32_t k = 0; k < n; ++k) {
        const Vec3d a(request.P[face_vertices[first + k]]), b(request.P[face_vertices[first + (k + 1) % n]]);
        const double pixel = std::min(view->pixel_size(a), view->pixel_size(b));
        if (pixel > 0 && std::isfinite(pixel)) longest = std::max(longest, length(b - a) / pixel);
        else longest = INFINITY;  // at the eye: keep the levels the size gives
      }
      first += n;
    }
    out.levels = subdivision_levels_on_screen(longest, out.levels);
  }
  for (int i = 0; i < out.levels; ++i) level = refine_catmull_clark(level);
  append_limit_triangles(level, out.mesh, out.triangle_control_face);
  return out;
}

}  // namespace darc
