#include "core/geometry/points/point_set_coverage.h"

#include "core/footprint/swept_polygon_coverage.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <numbers>

namespace darc {

namespace {

// The area of the intersection of two discs of radii a and b whose centres are d apart.
float lens_area(float d, float a, float b) {
  constexpr float pi = std::numbers::pi_v<float>;
  if (d >= a + b) return 0.0f;
  const float small = std::min(a, b);
  if (d <= std::abs(a - b)) return pi * small * small;  // one inside the other
  // Two circular segments, one of each disc, cut by the common chord.
  const float ca = std::clamp((d * d + a * a - b * b) / (2 * d * a), -1.0f, 1.0f);
  const float cb = std::clamp((d * d + b * b - a * a) / (2 * d * b), -1.0f, 1.0f);
  const float kite = 0.5f * std::sqrt(std::max(0.0f, (-d + a + b) * (d + a - b) * (d - a + b) * (d + a + b)));
  return a * a * std::acos(ca) + b * b * std::acos(cb) - kite;
}

// The area of the part of the disc of radius r centred at the origin with X <= x and Y <= y:
// the integral over X up to x of the disc's chord below y, by the antiderivative of the half
// chord sqrt(r^2 - X^2). In double: a rectangle's area is a difference of four of them.
double quadrant_area(double x, double y, double r) {
  if (x <= -r || y <= -r) return 0.0;
  x = std::min(x, r);
  y = std::min(y, r);
  const double r2 = r * r;
  auto half_chord_integral = [&](double X) {  // the integral of sqrt(r^2 - X^2) from 0 to X
    X = std::clamp(X, -r, r);
    return 0.5 * (X * std::sqrt(std::max(0.0, r2 - X * X)) + r2 * std::asin(X / r));
  };
  // Over |X| < w the line Y = y cuts the chord (the part below y is y + sqrt(r^2 - X^2) long);
  // beyond, the chord is all below y (y >= 0) or all above it (y < 0).
  const double w = std::sqrt(std::max(0.0, r2 - y * y));
  auto over = [&](double lo, double hi, auto&& antiderivative) {
    hi = std::min(hi, x);
    return hi > lo ? antiderivative(hi) - antiderivative(lo) : 0.0;
  };
  double area = over(-w, w, [&](double X) { return y * X + half_chord_integral(X); });
  if (y >= 0) {
    auto full_chord = [&](double X) { return 2.0 * half_chord_integral(X); };
    area += over(-r, -w, full_chord) + over(w, r, full_chord);
  }
  return area;
}

// The fraction of the rectangle [x0, x1] x [y0, y1] (relative to the disc's centre) the disc of
// radius r covers.
float rectangle_coverage(double x0, double x1, double y0, double y1, double r) {
  const double rect = (x1 - x0) * (y1 - y0);
  if (!(rect > 0.0)) return 0.0f;
  const double area =
      quadrant_area(x1, y1, r) - quadrant_area(x0, y1, r) - quadrant_area(x1, y0, r) + quadrant_area(x0, y0, r);
  return float(std::clamp(area / rect, 0.0, 1.0));
}

// Footprint axes closer to perpendicular than this (the cosine between them) are a rectangle:
// camera footprints are, to float rounding; sheared ones take the square of the disc's area.
constexpr float kRectangleCos = 1e-3f;

}  // namespace

float point_coverage(CoverageModel model, float x, float y, float r, float ax_x, float ax_y, float ay_x, float ay_y) {
  const float lx = std::sqrt(ax_x * ax_x + ax_y * ax_y), ly = std::sqrt(ay_x * ay_x + ay_y * ay_y);
  if (!(lx > 0.0f && ly > 0.0f)) return x * x + y * y <= r * r ? 1.0f : 0.0f;
  // Half the side of the square with the disc's area.
  const float half_side = 0.5f * std::sqrt(std::numbers::pi_v<float>) * r;
  float coverage = 0.0f;
  switch (model) {
    case CoverageModel::Square: {
      // Bands across each footprint axis: the disc's offset along the axis, and the footprint's
      // extents along it (its own side, and the other side's shadow on it when they are skewed).
      const float ux_x = ax_x / lx, ux_y = ax_y / lx, uy_x = ay_x / ly, uy_y = ay_y / ly;
      const float along_x = x * ux_x + y * ux_y, along_y = x * uy_x + y * uy_y;
      if (std::abs(ux_x * uy_x + ux_y * uy_y) < kRectangleCos) {
        // The exact area of the disc in the rectangle, in coordinates centred on the disc.
        const double hx = 0.5 * double(lx), hy = 0.5 * double(ly);
        return rectangle_coverage(-hx - along_x, hx - along_x, -hy - along_y, hy - along_y, double(r));
      }
      coverage = coverage_square(std::abs(along_x), half_side, lx, std::abs(ay_x * ux_x + ay_y * ux_y)) *
                 coverage_square(std::abs(along_y), half_side, ly, std::abs(ax_x * uy_x + ax_y * uy_y));
      break;
    }
    case CoverageModel::Box: {
      // The seed's box of half the sample spacing, across both axes of the ray frame.
      const float r_box = 0.25f * (lx + ly);
      coverage = coverage_box(std::abs(x), half_side, r_box) * coverage_box(std::abs(y), half_side, r_box);
      break;
    }
    case CoverageModel::Disc: {
      const float footprint_area = std::abs(ax_x * ay_y - ax_y * ay_x);
      const float r_disc = std::sqrt(footprint_area / std::numbers::pi_v<float>);
      if (!(r_disc > 0.0f)) return x * x + y * y <= r * r ? 1.0f : 0.0f;
      coverage = lens_area(std::sqrt(x * x + y * y), r, r_disc) / footprint_area;
      break;
    }
  }
  return std::clamp(coverage, 0.0f, 1.0f);
}

namespace {

// The fragment of a disc of radius r at `centre` (intersect_point_distance's body); its mask
// takes, among the `allowed` points, as many as the coverage is worth of them.
bool disc_fragment(const Vec3f& centre, float r, const DistanceRay& ray, CoverageModel model, PointFragmentHit& hit,
                   bool compute_mask, CoverageMask allowed) {
  if (!(r > 0.0f)) return false;
  const Vec3f rel = centre - ray.origin;
  const float depth = dot(rel, ray.dir);
  const float t = depth / ray.ray_length;
  if (!(t > ray.t_min && t < ray.t_max)) return false;
  const float x = dot(rel, ray.frame_x), y = dot(rel, ray.frame_y);
  const float d2 = x * x + y * y;
  // Cheapest rejection first: beyond the radius plus the footprint's reach nothing is covered.
  const float reach = ray.reach.at(std::max(0.0f, t));
  if (d2 > (r + reach) * (r + reach)) return false;
  const Vec3f ax = ray.footprint->axis_x(t), ay = ray.footprint->axis_y(t);
  const float ax_x = dot(ax, ray.frame_x), ax_y = dot(ax, ray.frame_y);
  const float ay_x = dot(ay, ray.frame_x), ay_y = dot(ay, ray.frame_y);
  const float lx = std::sqrt(ax_x * ax_x + ax_y * ax_y), ly = std::sqrt(ay_x * ay_x + ay_y * ay_y);
  // No footprint to speak of: coverage is the exact hit (the curves' rule, FootprintAt::binary).
  const bool binary = !(lx + ly > 2.0f * ray.footprint->min_radius);
  const float coverage = binary ? (d2 <= r * r ? 1.0f : 0.0f) : point_coverage(model, x, y, r, ax_x, ax_y, ay_x, ay_y);
  if (!(coverage > 0.0f)) return false;
  hit.t = t;
  hit.coverage = coverage;
  hit.distance = std::sqrt(d2);
  hit.mask = allowed;
  if (compute_mask && !binary) {
    // The mask points nearest the centre, as many as the coverage is worth (at least one): points
    // side by side in a footprint take different points, points in the same place the same ones.
    const int points = std::popcount(allowed);
    const int count = std::max(1, int(std::lround(coverage * float(points))));
    hit.mask = nearest_points_mask(FootprintSquare{ax_x, ax_y, ay_x, ay_y}, x, y, 0.0f, 0.0f, true, count, allowed);
  }
  return true;
}

}  // namespace

bool intersect_point_distance(const PointSet& set, size_t i, const DistanceRay& ray, CoverageModel model,
                              PointFragmentHit& hit, bool compute_mask) {
  if (!ray.valid) return false;
  if (!set.moving(i) || !ray.sweeps_shutter) {
    const bool moves = set.moving(i);
    return disc_fragment(moves ? set.center_at(i, ray.time) : set.center[i],
                         moves ? set.radius_at(i, ray.time) : set.radius[i], ray, model, hit, compute_mask,
                         kFullMask);
  }
  // A moving point under a ray that sweeps a stretch of the shutter: as a moving surface piece
  // (swept_polygon_coverage.h), its coverage averaged over the middles of kSweptPolygonTimes parts
  // of the stretch, each part's mask points (the times they stand for) taking where it is then.
  float coverage = 0;
  CoverageMask mask = 0;
  bool found = false;
  float best = 0;
  for (int part = 0; part < kSweptPolygonTimes; ++part) {
    const float middle = (float(part) + 0.5f) / float(kSweptPolygonTimes);
    const float time = ray.sweep_from + (ray.sweep_to - ray.sweep_from) * middle;
    PointFragmentHit h;
    if (!disc_fragment(set.center_at(i, time), set.radius_at(i, time), ray, model, h, compute_mask,
                       swept_polygon_part_points(part)))
      continue;
    coverage += h.coverage;
    mask |= h.mask;
    const float distance = std::abs(middle - 0.5f);
    if (!found || distance < best) {
      hit = h;
      best = distance;
    }
    found = true;
  }
  if (!found) return false;
  hit.coverage = coverage / float(kSweptPolygonTimes);
  hit.mask = compute_mask ? mask : kFullMask;
  return true;
}

}  // namespace darc
