#include "core/footprint/polygon_coverage.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace darc {

namespace {

// c + cu u + cv v >= 0. No default member values: the arrays of them below are written before
// they are read, and zeroing them took a fifth of this function's time.
struct HalfPlane {
  double c, cu, cv;
  double at(double u, double v) const { return c + cu * u + cv * v; }
};

// A vector held in an array that is written before it is read (Vec3d zeroes itself).
struct RawVec3 {
  double x, y, z;
  RawVec3& operator=(const Vec3d& v) {
    x = v.x, y = v.y, z = v.z;
    return *this;
  }
  Vec3d get() const { return {x, y, z}; }
};

struct Point2 {
  double u, v;
};

// The clipped square has at most 4 corners plus one per half-plane.
constexpr int kMaxClipCorners = 4 + kMaxPolygonCorners + 2;

// Clips the convex polygon in[0..n) by h (Sutherland-Hodgman); returns the corners kept in out.
// The cut parameter a / (a - b) depends only on the two values, so huge polygons (far outside
// the footprint) keep O(1) coordinates: the square is clipped by the lines, never the polygon
// by the square.
int clip(const Point2* in, int n, const HalfPlane& h, Point2* out) {
  int m = 0;
  for (int i = 0; i < n; ++i) {
    const Point2& p = in[i];
    const Point2& q = in[(i + 1) % n];
    const double a = h.at(p.u, p.v), b = h.at(q.u, q.v);
    if (a >= 0) out[m++] = p;
    if ((a >= 0) != (b >= 0)) {
      const double s = a / (a - b);
      out[m++] = {p.u + (q.u - p.u) * s, p.v + (q.v - p.v) * s};
    }
  }
  return m;
}

// Area and centroid of a polygon (shoelace).
double area_and_centroid(const Point2* p, int n, Point2& centroid) {
  double a2 = 0, cu = 0, cv = 0;
  for (int i = 0; i < n; ++i) {
    const Point2& s = p[i];
    const Point2& e = p[(i + 1) % n];
    const double cross = s.u * e.v - e.u * s.v;
    a2 += cross;
    cu += (s.u + e.u) * cross;
    cv += (s.v + e.v) * cross;
  }
  if (a2 == 0) {
    centroid = n > 0 ? p[0] : Point2{0, 0};
    return 0;
  }
  centroid = {cu / (3 * a2), cv / (3 * a2)};
  return 0.5 * std::abs(a2);
}

// Whether a mask point whose edge value is `value` is inside; a point exactly on the edge
// belongs to the side whose inward gradient (cu, cv) is lexicographically positive, so of two
// pieces sharing the edge (their values and gradients exact negations) exactly one owns it.
bool inside_edge(double value, const HalfPlane& h) {
  if (value != 0) return value > 0;
  return h.cu > 0 || (h.cu == 0 && h.cv > 0);
}

Vec3d newell_normal(std::span<const Vec3f> corners) {
  Vec3d n;
  const size_t count = corners.size();
  for (size_t i = 0; i < count; ++i) {
    const Vec3d p(corners[i]), q(corners[(i + 1) % count]);
    n.x += (p.y - q.y) * (p.z + q.z);
    n.y += (p.z - q.z) * (p.x + q.x);
    n.z += (p.x - q.x) * (p.y + q.y);
  }
  return n;
}

// The lexicographically smaller of two corners: both pieces that share an edge evaluate it from
// the same point, so their edge functions are exact negations.
const Vec3f& edge_base(const Vec3f& p, const Vec3f& q) {
  if (p.x != q.x) return p.x < q.x ? p : q;
  if (p.y != q.y) return p.y < q.y ? p : q;
  return p.z <= q.z ? p : q;
}

// The footprint square's corners.
constexpr Point2 kSquare[4] = {{-0.5, -0.5}, {0.5, -0.5}, {0.5, 0.5}, {-0.5, 0.5}};

// Whether every corner of the footprint square is outside h (then the polygon covers nothing:
// most pieces a walk offers are rejected by their first or second edge, before the others are
// made).
bool square_outside(const HalfPlane& h) {
  for (const Point2& c : kSquare)
    if (h.at(c.u, c.v) >= 0) return false;
  return true;
}

}  // namespace

bool polygon_coverage(const FootprintFrame& frame, std::span<const Vec3f> corners, PolygonFootprintHit& hit) {
  const int n = int(corners.size());
  if (n < 3 || n > kMaxPolygonCorners) return false;
  if (frame.outside_a_side(corners)) return false;
  const Vec3d normal = newell_normal(corners);
  // Edge planes first (one per corner), then the depth limits.
  HalfPlane planes[kMaxPolygonCorners + 2];
  int count = 0;
  // Per edge, what its value at a mask point is computed from (exactly as the neighbour does).
  RawVec3 edge_vector[kMaxPolygonCorners];
  RawVec3 edge_origin[kMaxPolygonCorners];
  double edge_sign = 1;
  const bool pencil = frame.form == FootprintForm::Pencil;
  // Depth along the sub-ray (u, v): pencil t = apex_t + k / g(u, v); parallel t = h(u, v) / nd.
  double k = 0, nd = 0;
  HalfPlane g{0, 0, 0}, h{0, 0, 0};
  int edge_count = 0;  // the first edge_count planes are edges
  if (pencil) {
    RawVec3 a[kMaxPolygonCorners];
    for (int i = 0; i < n; ++i) a[i] = Vec3d(corners[size_t(i)]) - frame.apex;
    k = dot(normal, a[0].get());
    if (!(k != 0) || !std::isfinite(k)) return false;  // seen edge-on from the apex
    edge_sign = (k > 0 ? 1.0 : -1.0) * frame.side;
    int edges = 0;
    for (int i = 0; i < n; ++i) {
      const Vec3d e = cross(a[i].get(), a[(i + 1) % n].get());
      if (e == Vec3d{}) continue;  // a repeated corner: no edge
      edge_vector[edges++] = e;
      planes[count++] = {edge_sign * dot(e, frame.d), edge_sign * dot(e, frame.ddx), edge_sign * dot(e, frame.ddy)};
      if (square_outside(planes[count - 1])) return false;
    }
    edge_count = edges;
    // g(u, v) = N . D(u, v) has the sign edge_sign where the polygon is met, and s = k / g.
    g = {dot(normal, frame.d), dot(normal, frame.ddx), dot(normal, frame.ddy)};
    const double s_min = frame.t_min - frame.apex_t, s_max = frame.t_max - frame.apex_t;
    if (std::isfinite(s_max))
      planes[count++] = {edge_sign * (s_max * g.c - k), edge_sign * s_max * g.cu, edge_sign * s_max * g.cv};
    if (std::isfinite(s_min))
      planes[count++] = {edge_sign * (k - s_min * g.c), -edge_sign * s_min * g.cu, -edge_sign * s_min * g.cv};
  } else {
    nd = dot(normal, frame.d);
    if (!(nd != 0) || !std::isfinite(nd)) return false;
    edge_sign = nd > 0 ? -1.0 : 1.0;
    int edges = 0;
    for (int i = 0; i < n; ++i) {
      const Vec3f& p = corners[size_t(i)];
      const Vec3f& q = corners[size_t((i + 1) % n)];
      const Vec3d m = cross(Vec3d(q) - Vec3d(p), frame.d);
      if (m == Vec3d{}) continue;  // a repeated corner, or an edge along d: no edge
      const Vec3d base(edge_base(p, q));
      edge_vector[edges] = m;
      edge_origin[edges++] = base;
      planes[count++] = {edge_sign * dot(m, frame.o - base), edge_sign * dot(m, frame.dox),
                         edge_sign * dot(m, frame.doy)};
      if (square_outside(planes[count - 1])) return false;
    }
    edge_count = edges;
    // h(u, v) = N . (X0 - O(u, v)); t = h / nd.
    h = {dot(normal, Vec3d(corners[0]) - frame.o), -dot(normal, frame.dox), -dot(normal, frame.doy)};
    const double sign = nd > 0 ? 1.0 : -1.0;
    if (std::isfinite(frame.t_min))
      planes[count++] = {sign * (h.c - frame.t_min * nd), sign * h.cu, sign * h.cv};
    if (std::isfinite(frame.t_max))
      planes[count++] = {sign * (frame.t_max * nd - h.c), -sign * h.cu, -sign * h.cv};
  }
  if (edge_count < 3) return false;
  for (int i = 0; i < count; ++i)
    if (!std::isfinite(planes[i].c) || !std::isfinite(planes[i].cu) || !std::isfinite(planes[i].cv)) return false;

  // The footprint square's corners against every half-plane: all outside one, nothing (the
  // edges were tested as they were made); inside all, everything.
  bool all_inside = true;
  for (int i = 0; i < count; ++i) {
    int in = 0;
    for (const Point2& c : kSquare) in += planes[i].at(c.u, c.v) >= 0;
    if (in == 0) return false;
    all_inside = all_inside && in == 4;
  }

  Point2 region[kMaxClipCorners], scratch[kMaxClipCorners];
  int corners_left = 4;
  std::copy(std::begin(kSquare), std::end(kSquare), region);
  double area = 1;
  Point2 centroid{0, 0};
  CoverageMask mask = kFullMask;
  if (!all_inside) {
    for (int i = 0; i < count && corners_left > 0; ++i) {
      corners_left = clip(region, corners_left, planes[i], scratch);
      std::copy(scratch, scratch + corners_left, region);
    }
    area = corners_left >= 3 ? area_and_centroid(region, corners_left, centroid) : 0.0;
    // Mask points: only those within the covered region's box can be inside.
    double u0 = 1, u1 = -1, v0 = 1, v1 = -1;
    for (int i = 0; i < corners_left; ++i) {
      u0 = std::min(u0, region[i].u), u1 = std::max(u1, region[i].u);
      v0 = std::min(v0, region[i].v), v1 = std::max(v1, region[i].v);
    }
    mask = 0;
    const double cell = 1.0 / kMaskSide;
    const int col0 = std::max(0, int(std::floor((u0 + 0.5) / cell - 0.5))),
              col1 = std::min(kMaskSide - 1, int(std::ceil((u1 + 0.5) / cell - 0.5)));
    const int row0 = std::max(0, int(std::floor((v0 + 0.5) / cell - 0.5))),
              row1 = std::min(kMaskSide - 1, int(std::ceil((v1 + 0.5) / cell - 0.5)));
    for (int row = row0; row <= row1; ++row)
      for (int col = col0; col <= col1; ++col) {
        const int b = row * kMaskSide + col;
        const Vec3d& pt = frame.point[size_t(b)];
        bool in = true;
        for (int i = 0; i < edge_count && in; ++i) {
          const double value =
              pencil ? edge_sign * dot(edge_vector[i].get(), pt)
                     : edge_sign * dot(edge_vector[i].get(), pt - edge_origin[i].get());
          in = inside_edge(value, planes[i]);
        }
        for (int i = edge_count; i < count && in; ++i) in = planes[i].at(mask_point_u(b), mask_point_v(b)) >= 0;
        if (in) mask |= CoverageMask{1} << b;
      }
    if (!(area > 0) && mask == 0) return false;
  }

  // Depths over the covered region: at the centroid (the sort depth and shading point) and the
  // range over its corners.
  auto depth = [&](double u, double v) {
    return pencil ? frame.apex_t + k / g.at(u, v) : h.at(u, v) / nd;
  };
  bool covers_centre = true;
  for (int i = 0; i < count && covers_centre; ++i) covers_centre = planes[i].at(0, 0) >= 0;
  if (covers_centre) centroid = {0, 0};
  double t = depth(centroid.u, centroid.v), t_near = t, t_far = t;
  const Point2* outline = all_inside ? kSquare : region;
  for (int i = 0; i < corners_left; ++i) {
    const double ti = depth(outline[i].u, outline[i].v);
    t_near = std::min(t_near, ti);
    t_far = std::max(t_far, ti);
  }
  if (!std::isfinite(t) || !std::isfinite(t_near) || !std::isfinite(t_far)) return false;
  hit.coverage = float(std::clamp(area, 0.0, 1.0));
  hit.mask = mask;
  hit.t = float(t);
  hit.t_near = float(t_near);
  hit.t_far = float(t_far);
  hit.u = float(centroid.u);
  hit.v = float(centroid.v);
  hit.covers_centre = covers_centre;
  hit.travel = Vec3f(frame.direction(centroid.u, centroid.v));
  return true;
}

double footprint_area_within(std::span<const FootprintHalfPlane> half_planes) {
  Point2 a[kMaxClipCorners], b[kMaxClipCorners];
  a[0] = {-0.5, -0.5}, a[1] = {0.5, -0.5}, a[2] = {0.5, 0.5}, a[3] = {-0.5, 0.5};
  int n = 4;
  Point2* in = a;
  Point2* out = b;
  for (size_t i = 0; i < half_planes.size() && i < size_t(kMaxPolygonCorners + 2) && n > 0; ++i) {
    n = clip(in, n, HalfPlane{half_planes[i].c, half_planes[i].cu, half_planes[i].cv}, out);
    std::swap(in, out);
  }
  Point2 centroid;
  return n >= 3 ? area_and_centroid(in, n, centroid) : 0.0;
}

}  // namespace darc
