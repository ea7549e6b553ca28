#include "core/geometry/surfaces/subdivision/catmull_clark_refinement.h"

#include <algorithm>
#include <string>

namespace darc {

namespace {

// The sharp edges at a vertex at one level: how many, and the far ends of the first two (all a
// crease needs).
struct SharpEdges {
  int count = 0;
  uint32_t far_end[2] = {0, 0};
};

template <typename IsSharp>
SharpEdges sharp_edges_at(const SubdivisionTopology& t, uint32_t v, const std::vector<uint32_t>& edges,
                          IsSharp is_sharp) {
  SharpEdges s;
  for (uint32_t e : edges) {
    if (!is_sharp(e)) continue;
    if (s.count < 2) s.far_end[s.count] = t.other_end(e, v);
    ++s.count;
  }
  return s;
}

// Catmull-Clark's smooth vertex rule for any valence n on a mesh of n-gons:
// (Q + 2 R + (n - 3) v) / n, Q the average face point, R the average edge midpoint.
Vec3d smooth_vertex_point(const SubdivisionLevel& p, const std::vector<Vec3d>& x, const std::vector<Vec3d>& face_points,
                          uint32_t v, const std::vector<uint32_t>& edges) {
  const SubdivisionTopology& t = p.topology;
  Vec3d q, r;
  uint32_t begin = t.vertex_corner_starts[v], end = t.vertex_corner_starts[v + 1];
  for (uint32_t i = begin; i < end; ++i) q += face_points[t.corner_face[t.vertex_corners[i]]];
  for (uint32_t e : edges) r += (x[v] + x[t.other_end(e, v)]) * 0.5;
  double n = double(edges.size());
  q = q / double(end - begin);
  r = r / n;
  return (q + r * 2.0 + x[v] * (n - 3.0)) / n;
}

Vec3d vertex_point_by_rule(const SubdivisionLevel& p, const std::vector<Vec3d>& x,
                           const std::vector<Vec3d>& face_points, uint32_t v, const std::vector<uint32_t>& edges,
                           VertexRule rule, const SharpEdges& sharp) {
  switch (rule) {
    case VertexRule::Corner:
      return x[v];
    case VertexRule::Crease:  // the cubic B-spline rule along the crease curve
      return (x[sharp.far_end[0]] + x[v] * 6.0 + x[sharp.far_end[1]]) / 8.0;
    case VertexRule::Smooth:
      break;
  }
  return smooth_vertex_point(p, x, face_points, v, edges);
}

// The new position of vertex v. Where a sharpness runs out at this level (the rule one level
// finer differs), the two rules' results are blended by the average sharpness of the edges and
// vertex that run out (clamped to 1): DeRose et al.'s fractional-sharpness rule.
Vec3d vertex_point(const SubdivisionLevel& p, const std::vector<Vec3d>& x, const std::vector<Vec3d>& face_points,
                   uint32_t v, const std::vector<uint32_t>& edges) {
  const SubdivisionTopology& t = p.topology;
  float vs = p.vertex_sharpness[v];
  SharpEdges now = sharp_edges_at(t, v, edges, [&](uint32_t e) { return p.edge_sharpness[e] > 0.0f; });
  SharpEdges next =
      sharp_edges_at(t, v, edges, [&](uint32_t e) { return refined_sharpness(p.edge_sharpness[e]) > 0.0f; });
  VertexRule rule_now = vertex_rule(now.count, vs);
  VertexRule rule_next = vertex_rule(next.count, refined_sharpness(vs));
  Vec3d pos_now = vertex_point_by_rule(p, x, face_points, v, edges, rule_now, now);
  if (rule_now == rule_next || rule_now == VertexRule::Smooth) return pos_now;
  float sum = 0;
  int running_out = 0;
  for (uint32_t e : edges) {
    if (p.edge_sharpness[e] > 0.0f && refined_sharpness(p.edge_sharpness[e]) == 0.0f) {
      sum += p.edge_sharpness[e];
      ++running_out;
    }
  }
  if (vs > 0.0f && refined_sharpness(vs) == 0.0f) {
    sum += vs;
    ++running_out;
  }
  double w = running_out > 0 ? std::clamp(double(sum) / running_out, 0.0, 1.0) : 1.0;
  Vec3d pos_next = vertex_point_by_rule(p, x, face_points, v, edges, rule_next, next);
  return pos_now * w + pos_next * (1.0 - w);
}

// The next level's values of a quantity x given per vertex of p and subdivided by p's rules
// (positions, or vertex-class texture coordinates): vertex points, then edge points, then face
// points, numbered as refine_catmull_clark numbers the child vertices.
std::vector<Vec3d> refine_vertex_values(const SubdivisionLevel& p, const std::vector<Vec3d>& x) {
  const SubdivisionTopology& t = p.topology;
  const uint32_t nv = t.vertex_count, ne = t.edge_count(), nf = t.face_count();
  std::vector<Vec3d> face_points(nf);
  for (uint32_t f = 0; f < nf; ++f) {
    Vec3d sum;
    for (uint32_t c = t.face_starts[f]; c < t.face_starts[f + 1]; ++c) sum += x[t.corner_vertex[c]];
    face_points[f] = sum / double(t.face_size(f));
  }
  std::vector<Vec3d> child(size_t(nv) + ne + nf);
  std::vector<uint32_t> edges;
  for (uint32_t v = 0; v < nv; ++v) {
    t.vertex_edges(v, edges);
    child[v] = edges.empty() ? x[v] : vertex_point(p, x, face_points, v, edges);
  }
  for (uint32_t e = 0; e < ne; ++e) {
    const Vec3d& a = x[t.edge_vertices[e][0]];
    const Vec3d& b = x[t.edge_vertices[e][1]];
    Vec3d midpoint = (a + b) * 0.5;
    double s = std::min(double(p.edge_sharpness[e]), 1.0);
    if (t.is_boundary_edge(e) || s >= 1.0) {
      child[nv + e] = midpoint;
      continue;
    }
    Vec3d smooth = (a + b + face_points[t.edge_faces[e][0]] + face_points[t.edge_faces[e][1]]) * 0.25;
    child[nv + e] = smooth * (1.0 - s) + midpoint * s;
  }
  for (uint32_t f = 0; f < nf; ++f) child[nv + ne + f] = face_points[f];
  return child;
}

}  // namespace

SubdivisionLevel refine_catmull_clark(const SubdivisionLevel& p) {
  const SubdivisionTopology& t = p.topology;
  const uint32_t nv = t.vertex_count, ne = t.edge_count();
  SubdivisionLevel child;
  child.points = refine_vertex_values(p, p.points);
  if (!p.vertex_st.empty()) child.vertex_st = refine_vertex_values(p, p.vertex_st);
  // Per-corner values are refined linearly inside their face (OpenSubdiv's "linear all"
  // face-varying rule): child corner order as the child faces below.
  if (!p.corner_st.empty()) {
    child.corner_st.reserve(4 * t.corner_vertex.size());
    for (uint32_t c = 0; c < t.corner_vertex.size(); ++c) {
      const uint32_t f = t.corner_face[c];
      Vec3d centre;
      for (uint32_t k = t.face_starts[f]; k < t.face_starts[f + 1]; ++k) centre += p.corner_st[k];
      centre = centre / double(t.face_size(f));
      const Vec3d here = p.corner_st[c];
      child.corner_st.insert(child.corner_st.end(), {here, (here + p.corner_st[t.next_corner(c)]) * 0.5, centre,
                                                     (here + p.corner_st[t.previous_corner(c)]) * 0.5});
    }
  }

  std::vector<uint32_t> child_sizes(t.corner_vertex.size(), 4);
  std::vector<uint32_t> child_vertices;
  child_vertices.reserve(4 * t.corner_vertex.size());
  for (uint32_t c = 0; c < t.corner_vertex.size(); ++c) {
    uint32_t f = t.corner_face[c];
    child_vertices.insert(child_vertices.end(), {t.corner_vertex[c], nv + t.corner_edge[c], nv + ne + f,
                                                 nv + t.corner_edge[t.previous_corner(c)]});
    child.face_hidden.push_back(p.face_hidden[f]);
    child.face_control_face.push_back(p.face_control_face[f]);
  }
  std::string error;  // a refined manifold is a manifold: build cannot fail here
  child.topology = *SubdivisionTopology::build(uint32_t(child.points.size()), child_sizes, child_vertices, error);

  child.edge_sharpness.assign(child.topology.edge_count(), 0.0f);
  for (uint32_t e = 0; e < ne; ++e) {
    float s = refined_sharpness(p.edge_sharpness[e]);
    if (s == 0.0f) continue;
    for (uint32_t end = 0; end < 2; ++end) {
      child.edge_sharpness[*child.topology.find_edge(t.edge_vertices[e][end], nv + e)] = s;
    }
  }
  child.vertex_sharpness.assign(child.points.size(), 0.0f);
  for (uint32_t v = 0; v < nv; ++v) child.vertex_sharpness[v] = refined_sharpness(p.vertex_sharpness[v]);
  return child;
}

}  // namespace darc
