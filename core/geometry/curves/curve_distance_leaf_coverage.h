// The coverage a leaf of a curve segment gives the footprint (curve_distance_intersector.cpp):
// a band at a distance (the seed's coverage forms, and their time-swept versions for a moving
// strand), the fall-off past a strand's end lines, a strand seen end-on, and the wings of a leaf
// that fan out past the segment's end lines. Inline, for the intersector's inner loop.
#pragma once

#include "core/footprint/polygon_coverage.h"
#include "core/geometry/curves/curve_distance_state.h"

namespace darc::curve_distance {

inline float orientation_scale(const DistanceState& s, float u) {
  if (!s.oriented) return 1.0f;
  Vec3f n = normalize(lerp(u, s.normal0, s.normal1));
  if (length_squared(n) == 0.0f) n = s.normal0;
  return std::abs(dot(n, s.dir));
}

// Coverage of a band of half-width hw at distance d whose 2D direction (along the strand) is
// (tx, ty), unit.
inline float band_coverage(const DistanceState& s, const FootprintAt& f, float d, float hw, float tx,
                           float ty) {
  if (f.binary) return d <= hw ? 1.0f : 0.0f;
  switch (s.model) {
    case CoverageModel::Box:
      return coverage_box(d, hw, f.r_box);
    case CoverageModel::Disc:
      return coverage_disc(d, hw, f.r_disc);
    case CoverageModel::Square: {
      float a, b;
      f.square_extents(-ty, tx, a, b);  // extents across the band
      return coverage_square(d, hw, a, b);
    }
  }
  return 0.0f;
}

// A band of half-width hw whose axis, across the unit normal (nx, ny), moves from signed
// distance d0 to d1 from the footprint centre during the interval: its coverage averaged over
// the interval, in closed form (swept_coverage.h).
inline float swept_band_coverage(const DistanceState& s, const FootprintAt& f, float d0, float d1, float hw,
                                 float nx, float ny) {
  if (f.binary) {
    // No footprint: the share of the time the axis is within hw of the centre.
    const double lo = std::min(d0, d1), hi = std::max(d0, d1);
    if (!(hi > lo)) return std::abs(d0) <= hw ? 1.0f : 0.0f;
    return float(std::max(0.0, std::min(hi, double(hw)) - std::max(lo, -double(hw))) / (hi - lo));
  }
  switch (s.model) {
    case CoverageModel::Box: return swept_coverage_box(d0, d1, hw, f.r_box);
    case CoverageModel::Disc: return swept_coverage_disc(d0, d1, hw, f.r_disc);
    case CoverageModel::Square: {
      float a, b;
      f.square_extents(nx, ny, a, b);
      return swept_coverage_square(d0, d1, hw, a, b);
    }
  }
  return 0.0f;
}

// The fraction of the footprint on the strand's side of a strand end: e is the distance from
// the end line to the ray centre, positive towards the strand; (tx, ty) the unit direction into
// the strand.
inline float end_falloff(const DistanceState& s, const FootprintAt& f, float e, float tx, float ty) {
  if (f.binary) return e >= 0.0f ? 1.0f : 0.0f;
  switch (s.model) {
    case CoverageModel::Box:
      return box_cdf(e, f.r_box);
    case CoverageModel::Disc:
      return disc_cdf(e, f.r_disc);
    case CoverageModel::Square: {
      float a, b;
      f.square_extents(tx, ty, a, b);
      return trapezoid_cdf(e, a, b);
    }
  }
  return 1.0f;
}

// Unit 2D direction of a ray-space vector, false when it is too short to have one.
inline bool unit_2d(const Vec3f& v, float min_length, float& x, float& y) {
  float l = hypot2(v.x, v.y);
  if (!(l > min_length)) return false;
  x = v.x / l;
  y = v.y / l;
  return true;
}

// A leaf seen end-on (its projected chord a point) is what the exact intersector sees of a
// ribbon facing the ray along its length: a disc of radius hw around the point (x, y). Its
// coverage is that of the square of equal area, the product of two perpendicular bands; exact
// for small discs under the square and box footprints (the disc form overestimates them by 4/pi).
inline float end_on_coverage(const DistanceState& s, const FootprintAt& f, float x, float y, float hw) {
  if (f.binary) return x * x + y * y <= hw * hw ? 1.0f : 0.0f;
  float equal_area_half_side = 0.5f * std::sqrt(std::numbers::pi_v<float>) * hw;
  return band_coverage(s, f, std::abs(y), equal_area_half_side, 1.0f, 0.0f) *
         band_coverage(s, f, std::abs(x), equal_area_half_side, 0.0f, 1.0f);
}

// The fraction of the footprint on the strand's side of both ends, from the fractions fs and fe
// on the strand's side of each. Ends facing each other (a short strand, into-strand directions
// opposite) cut a slab out of the footprint: fs + fe - 1, not the product fs * fe, which would
// let a strand much shorter than the footprint cover it as if it were long. Perpendicular ends
// keep the product (exact for a square footprint along them); ends facing the same way give
// min(fs, fe). Between these, blend by the cosine of the angle.
inline float both_ends_falloff(float fs, float fe, float cos_angle) {
  float product = fs * fe;
  if (cos_angle < 0.0f) return -cos_angle * std::max(0.0f, fs + fe - 1.0f) + (1.0f + cos_angle) * product;
  return cos_angle * std::min(fs, fe) + (1.0f - cos_angle) * product;
}

struct EndFalloff {
  bool start = false, end = false;
  bool start_is_joint = false, end_is_joint = false;  // cut only where the strand runs straight on
  Vec3f start_point, end_point;  // ray space
  float start_tx = 0, start_ty = 0, end_tx = 0, end_ty = 0;
};

// The unit 2D direction into a leaf at its end `e` from the control points next to it (the next
// one, else the ones after: coincident control points); false when the leaf is a point.
inline bool leaf_end_direction(const Vec3f& e, const Vec3f& n1, const Vec3f& n2, const Vec3f& n3, float& x,
                               float& y) {
  return unit_2d(n1 - e, 0.0f, x, y) || unit_2d(n2 - e, 0.0f, x, y) || unit_2d(n3 - e, 0.0f, x, y);
}

// The exact ribbon is the union of its leaves' slabs (between the lines perpendicular to each
// leaf at its ends, the exact intersector's leaf test) within the half-width of the leaf. Where a
// segment turns within less than its width (an S or a zig-zag much wider than it is long), the
// slabs of its leaves fan out past the segment's end lines: the exact renderers draw a bow-tie
// where the end lines alone leave a thin slab. These are the footprint points of that fan for
// one leaf: in its slab, within its half-width of its axis, and past the end lines that cut it.
// At the segment's ends the leaf's end line is the segment's own (the same line, without the
// rounding of the split), so a straight strand has no such points.
inline CoverageMask leaf_beyond_ends(const Vec3f cp[4], float u0, float u1, const EndFalloff& ends,
                                     bool cut_start, bool cut_end, const FootprintAt& f, float px, float py, float tx,
                                     float ty, float half_width) {
  const FootprintSquare sq{f.ax_x, f.ax_y, f.ay_x, f.ay_y};
  const CoverageMask start_side =
      cut_start ? half_plane_mask(sq, ends.start_point.x, ends.start_point.y, ends.start_tx, ends.start_ty) : kFullMask;
  const CoverageMask end_side =
      cut_end ? half_plane_mask(sq, ends.end_point.x, ends.end_point.y, ends.end_tx, ends.end_ty) : kFullMask;
  float x, y;
  CoverageMask leaf_slab = band_mask(sq, px, py, -ty, tx, half_width);
  if (u0 == 0.0f && cut_start)
    leaf_slab &= start_side;
  else if (leaf_end_direction(cp[0], cp[1], cp[2], cp[3], x, y))
    leaf_slab &= half_plane_mask(sq, cp[0].x, cp[0].y, x, y);
  else
    return 0;
  if (u1 == 1.0f && cut_end)
    leaf_slab &= end_side;
  else if (leaf_end_direction(cp[3], cp[2], cp[1], cp[0], x, y))
    leaf_slab &= half_plane_mask(sq, cp[3].x, cp[3].y, x, y);
  else
    return 0;
  return leaf_slab & ~(start_side & end_side);
}

}  // namespace darc::curve_distance
