#include "core/geometry/surfaces/polygon.h"

#include <fmt/format.h>

#include <cmath>
#include <cstdint>

namespace darc {

namespace {

// True when the 2D loop turns the same way at every corner (collinear corners aside): then its
// corners in order bound a convex region.
bool is_convex_loop(const std::vector<Vec2f>& loop) {
  const size_t n = loop.size();
  if (n < 3) return false;
  int sign = 0;
  for (size_t i = 0; i < n; ++i) {
    const Vec2f& p0 = loop[i];
    const Vec2f& p1 = loop[(i + 1) % n];
    const Vec2f& p2 = loop[(i + 2) % n];
    const double turn = double(p1.x - p0.x) * double(p2.y - p1.y) - double(p1.y - p0.y) * double(p2.x - p1.x);
    const int s = (turn > 0) - (turn < 0);
    if (s == 0) continue;
    if (sign != 0 && s != sign) return false;
    sign = s;
  }
  return sign != 0;
}

// A polygon whose area is below this fraction of its squared bounding-box diagonal is treated
// as degenerate (collinear or coincident points): its plane normal would be mostly rounding noise.
constexpr double kDegenerateAreaFraction = 1e-10;
// The fewest vertices of a loop, outer or hole.
constexpr int kMinLoopVertices = 3;

struct NewellPlane {
  Vec3d normal;  // not normalized: its length is twice the loop's area
  Vec3d centroid;
  double diagonal = 0;  // bounding-box diagonal of the loop
};

// Newell's method (Sutherland et al. 1974): the sum of edge cross products about the centroid
// is the area-weighted normal, robust for concave and slightly non-planar loops.
NewellPlane newell_plane(const std::vector<Vec3f>& loop) {
  NewellPlane plane;
  BBox box;
  for (const Vec3f& p : loop) {
    plane.centroid += Vec3d(p);
    box.extend(p);
  }
  plane.centroid = plane.centroid / double(loop.size());
  for (size_t i = 0; i < loop.size(); ++i) {
    Vec3d a = Vec3d(loop[i]) - plane.centroid;
    Vec3d b = Vec3d(loop[(i + 1) % loop.size()]) - plane.centroid;
    plane.normal += cross(a, b);
  }
  plane.diagonal = length(Vec3d(box.extent()));
  return plane;
}

bool all_finite(const std::vector<std::vector<Vec3f>>& loops) {
  for (const auto& loop : loops)
    for (const Vec3f& p : loop)
      if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) return false;
  return true;
}

bool is_planar(const std::vector<Vec3f>& loop, const NewellPlane& plane) {
  Vec3d n = normalize(plane.normal);
  for (const Vec3f& p : loop)
    if (std::abs(dot(n, Vec3d(p) - plane.centroid)) > kNonPlanarTolerance * plane.diagonal) return false;
  return true;
}

int dominant_axis(const Vec3d& n) {
  Vec3d a = abs(n);
  if (a.x >= a.y && a.x >= a.z) return 0;
  return a.y >= a.z ? 1 : 2;
}

}  // namespace

std::optional<PolygonShape> PolygonShape::make(const std::vector<std::vector<Vec3f>>& loops_world) {
  if (loops_world.empty() || loops_world[0].size() < 3 || !all_finite(loops_world)) return std::nullopt;
  NewellPlane plane = newell_plane(loops_world[0]);
  double area2 = length(plane.normal);
  if (!(area2 > kDegenerateAreaFraction * plane.diagonal * plane.diagonal)) return std::nullopt;

  PolygonShape shape;
  Vec3d n = plane.normal / area2;
  shape.normal = Vec3f(n);
  shape.plane_offset = dot(n, plane.centroid);
  shape.drop_axis = dominant_axis(n);
  int ax = (shape.drop_axis + 1) % 3, ay = (shape.drop_axis + 2) % 3;
  for (const auto& loop : loops_world) {
    if (loop.size() < 3) continue;  // a hole that encloses nothing
    shape.loop_starts.push_back(uint32_t(shape.points_2d.size()));
    for (const Vec3f& p : loop) {
      shape.points_2d.push_back({p[ax], p[ay]});
      shape.box.extend(p);
    }
  }
  shape.loop_starts.push_back(uint32_t(shape.points_2d.size()));
  if (shape.loop_starts.size() == 2 && is_convex_loop(shape.points_2d)) shape.convex_corners = loops_world[0];
  return shape;
}

bool PolygonShape::contains_2d(float x, float y) const {
  // Crossing-number test (W. R. Franklin's pnpoly): count edges crossed by the +x half-line
  // from the point; half-open in y so a vertex on the line is counted once.
  bool inside = false;
  for (size_t k = 0; k + 1 < loop_starts.size(); ++k) {
    uint32_t begin = loop_starts[k], end = loop_starts[k + 1];
    for (uint32_t i = begin, j = end - 1; i < end; j = i++) {
      const Vec2f& a = points_2d[i];
      const Vec2f& b = points_2d[j];
      if ((a.y > y) != (b.y > y) && x < (b.x - a.x) * (y - a.y) / (b.y - a.y) + a.x) inside = !inside;
    }
  }
  return inside;
}

bool PolygonShape::intersect(const Ray& ray, SurfaceHit& hit) const {
  Vec3d n(normal);
  Vec3d o(ray.o), d(ray.d);
  double denom = dot(n, d);
  if (!(denom != 0)) return false;  // parallel to the plane (or NaN)
  double t = (plane_offset - dot(n, o)) / denom;
  if (!(t > double(ray.tmin) && t < double(ray.tmax))) return false;
  Vec3d p = o + d * t;
  int ax = (drop_axis + 1) % 3, ay = (drop_axis + 2) % 3;
  if (!contains_2d(float(p[ax]), float(p[ay]))) return false;
  hit.t = float(t);
  hit.p = Vec3f(p);
  hit.ng = normal;
  hit.u = hit.v = 0;
  return true;
}

std::vector<PolygonShape> make_face_shapes(const std::vector<std::vector<Vec3f>>& loops_world, int source_face) {
  std::vector<PolygonShape> shapes;
  auto add = [&](const std::vector<std::vector<Vec3f>>& loops) {
    if (auto shape = PolygonShape::make(loops)) {
      shape->source_face = source_face;
      shapes.push_back(std::move(*shape));
    }
  };
  bool single_loop_to_check = loops_world.size() == 1 && loops_world[0].size() > 3 && all_finite(loops_world);
  if (single_loop_to_check) {
    const std::vector<Vec3f>& loop = loops_world[0];
    if (!is_planar(loop, newell_plane(loop))) {
      for (size_t i = 1; i + 1 < loop.size(); ++i) add({{loop[0], loop[i], loop[i + 1]}});
      return shapes;
    }
  }
  add(loops_world);
  return shapes;
}

std::vector<PolygonShape> make_points_general_polygons(const std::vector<int>& nloops_per_face,
                                                       const std::vector<int>& nverts_per_loop,
                                                       const std::vector<int>& indices,
                                                       const std::vector<Vec3f>& P_world, std::string& error) {
  // Validate every count and index before building anything, so a bad face fails the whole call.
  int64_t total_loops = 0;
  for (size_t f = 0; f < nloops_per_face.size(); ++f) {
    if (nloops_per_face[f] < 1) {
      error = fmt::format("face {} has {} loops (at least 1 required)", f, nloops_per_face[f]);
      return {};
    }
    total_loops += nloops_per_face[f];
  }
  if (total_loops != int64_t(nverts_per_loop.size())) {
    error = fmt::format("loop counts add up to {} loops but {} vertex counts were given", total_loops,
                        nverts_per_loop.size());
    return {};
  }
  int64_t total_verts = 0;
  for (size_t k = 0; k < nverts_per_loop.size(); ++k) {
    // RI Spec 3.2: a polygon (and each of its holes) has at least 3 vertices; a shorter loop
    // encloses nothing, so it is a count error as in Polygon and GeneralPolygon.
    if (nverts_per_loop[k] < kMinLoopVertices) {
      error = fmt::format("loop {} has {} vertices (at least {} required)", k, nverts_per_loop[k], kMinLoopVertices);
      return {};
    }
    total_verts += nverts_per_loop[k];
  }
  if (total_verts != int64_t(indices.size())) {
    error = fmt::format("vertex counts add up to {} vertices but {} indices were given", total_verts, indices.size());
    return {};
  }
  for (int index : indices) {
    if (index < 0 || size_t(index) >= P_world.size()) {
      error = fmt::format("vertex index {} out of range ({} points)", index, P_world.size());
      return {};
    }
  }

  std::vector<PolygonShape> shapes;
  size_t loop = 0, next_index = 0;
  std::vector<std::vector<Vec3f>> loops;
  for (size_t f = 0; f < nloops_per_face.size(); ++f) {
    loops.assign(size_t(nloops_per_face[f]), {});
    for (auto& points : loops) {
      int count = nverts_per_loop[loop++];
      points.reserve(size_t(count));
      for (int i = 0; i < count; ++i) points.push_back(P_world[size_t(indices[next_index++])]);
    }
    for (PolygonShape& shape : make_face_shapes(loops, int(f))) shapes.push_back(std::move(shape));
  }
  return shapes;
}

std::vector<PolygonShape> make_points_polygons(const std::vector<int>& nverts_per_face, const std::vector<int>& indices,
                                               const std::vector<Vec3f>& P_world, std::string& error) {
  std::vector<int> one_loop_each(nverts_per_face.size(), 1);
  return make_points_general_polygons(one_loop_each, nverts_per_face, indices, P_world, error);
}

bool PolygonShape::fit_st(const std::vector<Vec3f>& corners, const std::vector<float>& s, const std::vector<float>& t) {
  const size_t n = corners.size();
  if (n < 3 || s.size() != n || t.size() != n) return false;
  Vec3d centre{};
  for (const Vec3f& c : corners) centre += Vec3d(c);
  centre = centre / double(n);
  // Two axes of the plane, and each corner's coordinates along them.
  const Vec3d nrm(normal);
  const Vec3d e1 = normalize(std::abs(nrm.x) < 0.9 ? cross(nrm, Vec3d{1, 0, 0}) : cross(nrm, Vec3d{0, 1, 0}));
  const Vec3d e2 = cross(nrm, e1);
  // Least squares for value = a + b x + c y: the 3x3 normal equations, solved by Cramer's rule.
  double m[3][3] = {}, rs[3] = {}, rt[3] = {};
  for (size_t i = 0; i < n; ++i) {
    const Vec3d w = Vec3d(corners[i]) - centre;
    const double row[3] = {1, dot(w, e1), dot(w, e2)};
    for (int r = 0; r < 3; ++r) {
      for (int c = 0; c < 3; ++c) m[r][c] += row[r] * row[c];
      rs[r] += row[r] * s[i];
      rt[r] += row[r] * t[i];
    }
  }
  auto det3 = [](const double a[3][3]) {
    return a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) - a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
           a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
  };
  const double det = det3(m);
  if (!(std::abs(det) > 1e-12 * m[1][1] * m[2][2]) || !std::isfinite(det)) return false;
  auto solve = [&](const double rhs[3], double out[3]) {
    for (int k = 0; k < 3; ++k) {
      double a[3][3];
      for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) a[r][c] = c == k ? rhs[r] : m[r][c];
      out[k] = det3(a) / det;
    }
  };
  double cs[3], ct[3];
  solve(rs, cs);
  solve(rt, ct);
  const Vec3d gs = e1 * cs[1] + e2 * cs[2], gt = e1 * ct[1] + e2 * ct[2];
  s_gradient = Vec3f(gs);
  t_gradient = Vec3f(gt);
  s_offset = float(cs[0] - dot(gs, centre));
  t_offset = float(ct[0] - dot(gt, centre));
  has_st = true;
  return true;
}

}  // namespace darc
