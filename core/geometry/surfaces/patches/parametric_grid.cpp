#include "core/geometry/surfaces/patches/parametric_grid.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>

namespace darc {

namespace {

// dP/du x dP/dv counts as vanishing below this fraction of |dP/du| |dP/dv| (the sine of the angle
// between them: 1e-9 is far below any real fold, far above double rounding of unit derivatives).
constexpr double kParallelDerivatives = 1e-9;
// Where the normal vanishes (a collapsed edge, a sphere's pole), it is taken this fraction of the
// way from the point towards the span's centre: the normal there is off the limit by about this
// fraction of the span's turn (0.01 degrees for a quarter circle), and the derivatives are well
// above rounding.
constexpr double kDegenerateNudge = 1e-4;

Vec3d unit_normal(const SurfaceSample& s) {
  const Vec3d n = cross(s.dPdu, s.dPdv);
  const double l = length(n);
  if (!(l > kParallelDerivatives * length(s.dPdu) * length(s.dPdv))) return {};
  return n / l;
}

double span_centre(const std::vector<double>& edges, int i) { return 0.5 * (edges[size_t(i)] + edges[size_t(i) + 1]); }

// The unit normal of span (i, j) at (u, v), from a point just inside the span where it vanishes;
// zero when the span is degenerate there too.
Vec3d span_normal(const SpanLayout& layout, const SpanEvaluator& evaluate, int i, int j, double u, double v) {
  Vec3d n = unit_normal(evaluate(i, j, u, v));
  if (n != Vec3d{}) return n;
  const double uc = span_centre(layout.u_edges, i), vc = span_centre(layout.v_edges, j);
  return unit_normal(evaluate(i, j, u + (uc - u) * kDegenerateNudge, v + (vc - v) * kDegenerateNudge));
}

double angle_between(const Vec3d& a, const Vec3d& b) {
  if (a == Vec3d{} || b == Vec3d{}) return 0;  // no normal to compare (a degenerate point)
  // atan2 of |a x b| and a . b: accurate for small angles, where acos of the dot is not.
  return std::atan2(length(cross(a, b)), dot(a, b));
}

// The deviation a second difference D makes from the tangent plane with unit normal n: its normal
// component (a tangential one only reparameterises a flat surface); all of it where n is unknown.
double off_plane(const Vec3d& D, const Vec3d& n) { return n == Vec3d{} ? length(D) : std::abs(dot(D, n)); }

// The fewest segments around a closed direction that enclose an area (a triangle's three sides).
constexpr size_t kMinClosedSegments = 3;

int segments_for(double needed) {
  if (!(needed > 1)) return 1;  // also NaN from a non-finite probe
  return int(std::min(std::ceil(needed), double(kMaxSegmentsPerSpan)));
}

struct SpanSegments {
  int u = 1, v = 1;
};

// The segments span (i, j) needs, from its probes: a chord over parameter step h deviates from the
// curve by |P''| h^2 / 8, a bilinear cell's diagonal from its surface by |P_uv| h_u h_v / 4, and
// the normal turns by the probes' turn scaled to the step.
SpanSegments span_segments(const SpanLayout& layout, const SpanEvaluator& evaluate, int i, int j,
                           const DicingView* view) {
  constexpr int K = kProbeIntervals;
  const double u0 = layout.u_edges[size_t(i)], u1 = layout.u_edges[size_t(i) + 1];
  const double v0 = layout.v_edges[size_t(j)], v1 = layout.v_edges[size_t(j) + 1];
  Vec3d P[K + 1][K + 1], N[K + 1][K + 1];
  Vec3d lo{INFINITY, INFINITY, INFINITY}, hi = -lo;
  double pixel = INFINITY;  // the smallest pixel over the probes (where the span is nearest)
  for (int a = 0; a <= K; ++a)
    for (int b = 0; b <= K; ++b) {
      const double u = a == K ? u1 : u0 + (u1 - u0) * a / K, v = b == K ? v1 : v0 + (v1 - v0) * b / K;
      P[a][b] = evaluate(i, j, u, v).P;
      N[a][b] = span_normal(layout, evaluate, i, j, u, v);
      lo = min(lo, P[a][b]);
      hi = max(hi, P[a][b]);
      if (view) pixel = std::min(pixel, view->pixel_size(P[a][b]));
    }
  const double size = length(hi - lo);
  if (!(size > 0) || !std::isfinite(size)) return {};  // a point, or a surface no triangle can show
  const double tolerance = kMaxDeviationFraction * size;
  double bend_u = 0, bend_v = 0, twist = 0, turn_u = 0, turn_v = 0;
  for (int a = 0; a <= K; ++a)
    for (int b = 0; b <= K; ++b) {
      if (a > 0 && a < K) bend_u = std::max(bend_u, off_plane(P[a + 1][b] - P[a][b] * 2.0 + P[a - 1][b], N[a][b]));
      if (b > 0 && b < K) bend_v = std::max(bend_v, off_plane(P[a][b + 1] - P[a][b] * 2.0 + P[a][b - 1], N[a][b]));
      if (a < K && b < K)
        twist = std::max(twist, off_plane(P[a + 1][b + 1] - P[a + 1][b] - P[a][b + 1] + P[a][b], N[a][b]));
      if (a < K) turn_u = std::max(turn_u, angle_between(N[a][b], N[a + 1][b]));
      if (b < K) turn_v = std::max(turn_v, angle_between(N[a][b], N[a][b + 1]));
    }
  // The probes are K steps apart, so n segments shrink each probe step by K / n. A cell's diagonal
  // turns by up to sqrt(2) times one side's turn where the surface bends both ways (a sphere).
  auto for_bend = [&](double bend, double tol) { return K * std::sqrt(bend / (8 * tol)); };
  auto for_twist = [&](double tol) { return K * std::sqrt(twist / (4 * tol)); };
  const double side_turn = kMaxNormalTurn / std::sqrt(2.0);
  const double surface_u = std::max({for_bend(bend_u, tolerance), for_twist(tolerance), K * turn_u / side_turn});
  const double surface_v = std::max({for_bend(bend_v, tolerance), for_twist(tolerance), K * turn_v / side_turn});
  if (!view || !(pixel > 0) || !std::isfinite(pixel)) return {segments_for(surface_u), segments_for(surface_v)};
  // On the screen: the deviation in pixels, and the normal rule only down to kMinSegmentPixels.
  double length_u = 0, length_v = 0;  // the longest probe line each way
  for (int b = 0; b <= K; ++b) {
    double lu = 0, lv = 0;
    for (int a = 0; a < K; ++a) {
      lu += length(P[a + 1][b] - P[a][b]);
      lv += length(P[b][a + 1] - P[b][a]);
    }
    length_u = std::max(length_u, lu);
    length_v = std::max(length_v, lv);
  }
  // Half the tolerance to each direction's bend: a cell's diagonal sags by the sum of both (a
  // sphere's triangles would otherwise leave twice the deviation asked for).
  const double screen_tolerance = 0.5 * kMaxDeviationPixels * pixel, segment = kMinSegmentPixels * pixel;
  const double screen_u = std::max({for_bend(bend_u, screen_tolerance), for_twist(screen_tolerance),
                                    std::min(K * turn_u / side_turn, length_u / segment)});
  const double screen_v = std::max({for_bend(bend_v, screen_tolerance), for_twist(screen_tolerance),
                                    std::min(K * turn_v / side_turn, length_v / segment)});
  return {segments_for(std::min(surface_u, screen_u)), segments_for(std::min(surface_v, screen_v))};
}

size_t grid_vertices(const std::vector<int>& segments, bool closed) {
  size_t n = closed ? 0 : 1;
  for (int s : segments) n += size_t(s);
  return n;
}

// Scales every count down together (at least 1 each) until it fits kMaxVerticesPerSurface.
void coarsen_to_cap(GridDensity& d, const SpanLayout& layout) {
  for (;;) {
    const double vertices =
        double(grid_vertices(d.u_segments, layout.u_closed)) * double(grid_vertices(d.v_segments, layout.v_closed));
    if (vertices <= double(kMaxVerticesPerSurface)) return;
    const double scale = std::sqrt(double(kMaxVerticesPerSurface) / vertices);
    bool changed = false;
    for (std::vector<int>* counts : {&d.u_segments, &d.v_segments})
      for (int& c : *counts) {
        const int scaled = std::max(1, int(std::floor(c * scale)));
        changed |= scaled != c;
        c = scaled;
      }
    if (!changed) return;  // one segment per span already: as large as the input
  }
}

// One line of grid vertices in one direction: its parameter, the span that evaluates it, and the
// span on the other side of it when it lies on an edge between two (-1 if none), at its
// parameter there (a closed seam's is the last edge).
struct GridLine {
  double t = 0;
  int span = 0;
  int other_span = -1;
  double other_t = 0;
};

std::vector<GridLine> grid_lines(const std::vector<double>& edges, const std::vector<int>& segments, bool closed) {
  const int spans = int(segments.size());
  std::vector<GridLine> lines;
  for (int i = 0; i < spans; ++i) {
    const double t0 = edges[size_t(i)], t1 = edges[size_t(i) + 1];
    const int n = segments[size_t(i)];
    for (int k = 0; k < n; ++k) {
      GridLine line{k == 0 ? t0 : t0 + (t1 - t0) * k / n, i};
      if (k == 0 && i > 0) line.other_span = i - 1, line.other_t = t0;
      if (k == 0 && i == 0 && closed) line.other_span = spans - 1, line.other_t = edges.back();
      lines.push_back(line);
    }
  }
  if (!closed) lines.push_back({edges.back(), spans - 1});
  return lines;
}

// Vertices whose normal vanished in every span (a span collapsed to a line or a point) take the
// area-weighted normal of their triangles, and (0, 0, 1) when those have no area either: such
// triangles are never hit, so any unit vector keeps the data valid.
void fill_missing_normals(TriangleMeshData& mesh, const std::vector<Vec3d>& P, std::vector<Vec3d>& N) {
  std::vector<Vec3d> face_sum(N.size());
  for (size_t t = 0; t < mesh.indices.size(); t += 3) {
    const uint32_t a = mesh.indices[t], b = mesh.indices[t + 1], c = mesh.indices[t + 2];
    const Vec3d n = cross(P[b] - P[a], P[c] - P[a]);
    for (uint32_t v : {a, b, c}) face_sum[v] += n;
  }
  for (size_t v = 0; v < N.size(); ++v) {
    if (N[v] != Vec3d{}) continue;
    N[v] = normalize(face_sum[v]);
    if (N[v] == Vec3d{}) N[v] = {0, 0, 1};
  }
}

}  // namespace

SurfaceSample rational_sample(const HomogeneousPoint& H, const HomogeneousPoint& dHdu, const HomogeneousPoint& dHdv) {
  SurfaceSample s;
  s.P = H.xyz / H.w;
  s.dPdu = (dHdu.xyz - s.P * dHdu.w) / H.w;
  s.dPdv = (dHdv.xyz - s.P * dHdv.w) / H.w;
  return s;
}

bool valid_control_points(const std::vector<HomogeneousPoint>& points, std::string& error) {
  for (size_t k = 0; k < points.size(); ++k) {
    const HomogeneousPoint& p = points[k];
    if (!(std::isfinite(p.xyz.x) && std::isfinite(p.xyz.y) && std::isfinite(p.xyz.z) && std::isfinite(p.w))) {
      error = fmt::format("point {} is not finite", k);
      return false;
    }
    // A weight of 0 puts the point at infinity, a negative one lets the surface pass through it.
    if (!(p.w > 0)) {
      error = fmt::format("point {} has weight w = {}: weights must be positive", k, p.w);
      return false;
    }
  }
  return true;
}

GridDensity choose_grid_density(const SpanLayout& layout, const SpanEvaluator& evaluate, const DicingView* view) {
  const int spans_u = int(layout.u_edges.size()) - 1, spans_v = int(layout.v_edges.size()) - 1;
  GridDensity d{std::vector<int>(size_t(spans_u), 1), std::vector<int>(size_t(spans_v), 1)};
  for (int j = 0; j < spans_v; ++j)
    for (int i = 0; i < spans_u; ++i) {
      const SpanSegments s = span_segments(layout, evaluate, i, j, view);
      d.u_segments[size_t(i)] = std::max(d.u_segments[size_t(i)], s.u);
      d.v_segments[size_t(j)] = std::max(d.v_segments[size_t(j)], s.v);
    }
  coarsen_to_cap(d, layout);
  // A closed direction of fewer than 3 segments folds onto itself (a periodic mesh of one patch):
  // 3 give it an area.
  for (auto [closed, counts] : {std::pair{layout.u_closed, &d.u_segments}, std::pair{layout.v_closed, &d.v_segments}})
    if (closed && grid_vertices(*counts, true) < kMinClosedSegments)
      counts->back() += int(kMinClosedSegments - grid_vertices(*counts, true));
  return d;
}

TriangleMeshData triangulate_grid(const SpanLayout& layout, const SpanEvaluator& evaluate, const GridDensity& density) {
  const std::vector<GridLine> us = grid_lines(layout.u_edges, density.u_segments, layout.u_closed);
  const std::vector<GridLine> vs = grid_lines(layout.v_edges, density.v_segments, layout.v_closed);
  const size_t nu = us.size(), nv = vs.size();
  std::vector<Vec3d> P(nu * nv), N(nu * nv);
  TriangleMeshData mesh;
  mesh.uv.resize(nu * nv);
  for (size_t b = 0; b < nv; ++b)
    for (size_t a = 0; a < nu; ++a) {
      const GridLine &u = us[a], &v = vs[b];
      const size_t k = a + b * nu;
      P[k] = evaluate(u.span, v.span, u.t, v.t).P;
      mesh.uv[k] = {float(u.t), float(v.t)};
      // The sum of the unit normals of every span that holds the vertex: one normal per vertex
      // where patches meet at a crease, and the same normal where they meet smoothly.
      Vec3d sum;
      for (int su = 0; su < 2; ++su)
        for (int sv = 0; sv < 2; ++sv) {
          if ((su && u.other_span < 0) || (sv && v.other_span < 0)) continue;
          sum += span_normal(layout, evaluate, su ? u.other_span : u.span, sv ? v.other_span : v.span,
                             su ? u.other_t : u.t, sv ? v.other_t : v.t);
        }
      N[k] = normalize(sum);
    }
  // Cells: the last line of a closed direction joins the first.
  const size_t cells_u = layout.u_closed ? nu : nu - 1, cells_v = layout.v_closed ? nv : nv - 1;
  mesh.indices.reserve(cells_u * cells_v * 6);
  for (size_t b = 0; b < cells_v; ++b)
    for (size_t a = 0; a < cells_u; ++a) {
      const size_t a1 = (a + 1) % nu, b1 = (b + 1) % nv;
      const uint32_t v00 = uint32_t(a + b * nu), v10 = uint32_t(a1 + b * nu);
      const uint32_t v01 = uint32_t(a + b1 * nu), v11 = uint32_t(a1 + b1 * nu);
      // (b - a) x (c - a) of both is the cell's dP/du x dP/dv, since u runs v00 -> v10.
      mesh.indices.insert(mesh.indices.end(), {v00, v10, v11, v00, v11, v01});
    }
  fill_missing_normals(mesh, P, N);
  mesh.P.resize(P.size());
  mesh.N.resize(N.size());
  for (size_t k = 0; k < P.size(); ++k) {
    mesh.P[k] = Vec3f(P[k]);
    mesh.N[k] = Vec3f(N[k]);
  }
  return mesh;
}

TriangleMeshData tessellate_spans(const SpanLayout& layout, const SpanEvaluator& evaluate, const DicingView* view) {
  return triangulate_grid(layout, evaluate, choose_grid_density(layout, evaluate, view));
}

}  // namespace darc
