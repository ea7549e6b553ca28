#include "core/geometry/curves/curve_distance_intersector.h"

#include "core/geometry/curves/curve_distance_leaf_coverage.h"
#include "core/geometry/curves/curve_distance_state.h"
#include "core/geometry/curves/curve_intersector.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "core/math/curve_basis.h"
#include "core/geometry/curves/curve_ray_space.h"

namespace darc {

namespace {

using namespace curve_distance;

void distance_leaf(const Vec3f cp[4], const float width[4], float u0, float u1, const EndFalloff& ends,
                   DistanceState& s) {
  float chord_x = cp[3].x - cp[0].x, chord_y = cp[3].y - cp[0].y;
  float chord_length2 = chord_x * chord_x + chord_y * chord_y;
  float max_half_width = 0.5f * std::max(std::max(width[0], width[1]), std::max(width[2], width[3]));
  float point_chord = kPointChordFraction * 2.0f * std::max(max_half_width, 0.0f);
  // The closest approach of the ray to the leaf's chord, clamped to the leaf: no end
  // half-plane tests here, since a strand beside the footprint covers it whichever leaf
  // reports it (the best leaf per segment wins, the best segment per strand in the A-buffer).
  const bool end_on = chord_length2 <= point_chord * point_chord;
  const float w_unclamped = end_on ? 0.0f : (-cp[0].x * chord_x - cp[0].y * chord_y) / chord_length2;
  float w = end_on ? (cp[0].z <= cp[3].z ? 0.0f : 1.0f) : std::clamp(w_unclamped, 0.0f, 1.0f);
  float u = std::clamp(u0 + (u1 - u0) * w, u0, u1);
  float half_width = 0.5f * bezier_evaluate(width, w) * orientation_scale(s, u);
  if (!(half_width > 0.0f)) return;
  Vec3f pc = bezier_evaluate(cp, w);
  float t = pc.z / s.ray_length;
  if (!s.ahead(t)) return;
  // A start patch leaning along the ray (DistanceRay::start) has sub-rays that start past a
  // strand near it, others before it: a neighbour beside it can be met at depth <= t_min on the
  // centre ray by the sub-rays from the patch's near side, and one just ahead of the centre is
  // not met by those from its far side. Only the sub-rays that start before the strand where
  // they cross it count: to first order a half-plane of the footprint (StartCut).
  t = std::max(t, s.t_min);
  float d = hypot2(pc.x, pc.y);
  FootprintAt f = s.footprint_at(t);
  float tx = 1.0f, ty = 0.0f;
  const Vec3f tangent = bezier_derivative(cp, w);
  if (!unit_2d(tangent, 0.0f, tx, ty) && !unit_2d(cp[3] - cp[0], 0.0f, tx, ty)) {
    tx = 1.0f;
    ty = 0.0f;
  }
  const bool cut_start =
      ends.start && (!ends.start_is_joint || tx * ends.start_tx + ty * ends.start_ty > kDistinctPieceCos);
  const bool cut_end = ends.end && (!ends.end_is_joint || -(tx * ends.end_tx + ty * ends.end_ty) > kDistinctPieceCos);
  float coverage;
  float beyond_leaf = 0.0f;
  float leaf_time = -1.0f;
  bool swept = false;
  SweptLine sweep;
  if (s.keys && !end_on) {
    // The strand point at u moves from the interval's start to its end; across the band (whose
    // direction is frozen at the middle: turns within an interval are small) from d0 to d1.
    const float nx = -ty, ny = tx;
    const Vec3f at_middle = bezier_evaluate(s.mid_cp, u);
    const float d_mid = pc.x * nx + pc.y * ny;
    const Vec3f from = bezier_evaluate(s.keys->from.data(), u) - at_middle;
    const Vec3f to = bezier_evaluate(s.keys->to.data(), u) - at_middle;
    const float d0 = d_mid + from.x * nx + from.y * ny, d1 = d_mid + to.x * nx + to.y * ny;
    coverage = swept_band_coverage(s, f, d0, d1, half_width, nx, ny);
    // The centre's offset along the strand from pc (not 0 where pc is the leaf's clamped end):
    // the band is no infinite line past the leaf's end (below, where no end line cuts it).
    if (w_unclamped < 0.0f || w_unclamped > 1.0f) beyond_leaf = std::abs(pc.x * tx + pc.y * ty);
    // Its mask points are those it passes at their times (mask_point_time).
    swept = true;
    sweep = {s.time_from, s.time_to, d0 - d_mid, d1 - d_mid, s.ends_shutter};
    // Shaded as it is when it passes the footprint's centre (nearest it, if it does not).
    const float cross = d0 == d1 ? 0.5f : std::clamp(d0 / (d0 - d1), 0.0f, 1.0f);
    leaf_time = s.shutter_from + (s.shutter_to - s.shutter_from) * cross;
  } else {
    // Past a segment's end that an end line cuts, the band's distance is across the strand
    // only: the end line's fall-off (below) accounts for the distance along it. The distance to
    // the end point instead (the leaf's closest approach) counted the offset twice and lost about
    // 0.06 pixel of every cut end's length (a strand 12 pixels long: 1 % of its alpha).
    // Only past the end line itself: a curved or wide segment's leaf can end short of it.
    const bool past_cut_end =
        !end_on &&
        ((w_unclamped < 0.0f && u0 == 0.0f && cut_start &&
          ends.start_point.x * ends.start_tx + ends.start_point.y * ends.start_ty > 0.0f) ||
         (w_unclamped > 1.0f && u1 == 1.0f && cut_end && ends.end_point.x * ends.end_tx + ends.end_point.y * ends.end_ty > 0.0f));
    const float d_band = past_cut_end ? std::abs(pc.y * tx - pc.x * ty) : d;
    coverage = end_on ? end_on_coverage(s, f, pc.x, pc.y, half_width) : band_coverage(s, f, d_band, half_width, tx, ty);
  }
  StartCut cut;
  CoverageMask cut_points = 0;
  float started = 1.0f;
  // Each sub-ray starts t_min past its origin.
  const float start_offset = s.t_min * s.ray_length + s.start_margin;
  const bool near_start = s.has_start && pc.z - half_width < s.start_depth_max + start_offset;
  if (near_start && coverage > 0.0f) {
    // The strand's depth along its projected tangent: dz per unit of 2D length (0 seen side-on;
    // an end-on leaf keeps its depth).
    const float along = hypot2(tangent.x, tangent.y);
    const float slope = along > std::abs(tangent.z) * 1e-3f ? tangent.z / along : 0.0f;
    cut.cu = s.start_du - slope * (f.ax_x * tx + f.ax_y * ty);
    cut.cv = s.start_dv - slope * (f.ay_x * tx + f.ay_y * ty);
    cut.z0 = pc.z - slope * (pc.x * tx + pc.y * ty) - start_offset;
    const float share = cut.share();
    if (!(share > 0.0f)) return;
    if (share < 1.0f) {
      // The cut and the band are not independent (a strand beside the patch is met only by the
      // sub-rays on its side, whose origins lie at their own depths): the share of the band's
      // part of the footprint that is cut, exactly, and its mask points.
      const double across_u = -ty * f.ax_x + tx * f.ax_y, across_v = -ty * f.ay_x + tx * f.ay_y;
      const double across_0 = -ty * pc.x + tx * pc.y;
      const FootprintHalfPlane planes[3] = {{half_width + across_0, -across_u, -across_v},
                                            {half_width - across_0, across_u, across_v},
                                            {cut.z0, -cut.cu, -cut.cv}};
      const double band_area = footprint_area_within(std::span(planes, 2));
      started = band_area > 0 ? float(std::min(1.0, footprint_area_within(planes) / band_area)) : share;
      if (!(started > 0.0f)) return;
      const FootprintSquare sq{f.ax_x, f.ax_y, f.ay_x, f.ay_y};
      cut_points = band_mask(sq, pc.x, pc.y, -ty, tx, half_width) & cut.mask();
    }
  }
  float fs = 1.0f, fe = 1.0f;
  if (cut_start)
    fs = end_falloff(s, f, -(ends.start_point.x * ends.start_tx + ends.start_point.y * ends.start_ty), ends.start_tx,
                     ends.start_ty);
  if (cut_end)
    fe = end_falloff(s, f, -(ends.end_point.x * ends.end_tx + ends.end_point.y * ends.end_ty), ends.end_tx,
                     ends.end_ty);
  if (beyond_leaf > 0.0f && !cut_start && !cut_end) coverage *= end_falloff(s, f, -beyond_leaf, tx, ty);
  const float within_ends = cut_start && cut_end
                                ? both_ends_falloff(fs, fe, ends.start_tx * ends.end_tx + ends.start_ty * ends.end_ty)
                                : fs * fe;
  // The part of the leaf past the end lines (a fan wider than the segment is long) is counted by
  // its points, which add up over the leaves (adjacent slabs split a footprint between them).
  float beyond = 0.0f;
  if (within_ends < 1.0f && !end_on && !f.binary && coverage > 0.0f &&
      half_width >= kMinFanHalfWidthInFootprints * std::max(hypot2(f.ax_x, f.ax_y), hypot2(f.ay_x, f.ay_y))) {
    CoverageMask m = leaf_beyond_ends(cp, u0, u1, ends, cut_start, cut_end, f, pc.x, pc.y, tx, ty, half_width);
    s.beyond_ends |= m;
    beyond = float(mask_count(m)) / float(kMaskSide * kMaskSide);
  }
  coverage *= within_ends * started;
  if (coverage > 0.0f) s.add_piece({coverage, pc.x, pc.y, tx, ty, half_width, end_on, cut_start, cut_end, swept, sweep});
  s.best_within_ends = std::max(s.best_within_ends, coverage);
  // The best leaf (its depth and shading point) is chosen by all it covers.
  coverage = std::min(1.0f, coverage + beyond);
  if (!(coverage > 0.0f)) return;
  // Equal coverages (every leaf within the strand's width of the ray covers all of a footprint
  // narrower than the strand) go to the leaf nearest the ray: its point is the strand's closest
  // approach, where the shading parameter u and the depth belong. First-found would make u
  // piecewise constant over each leaf's reach (discs of one colour along wide ribbons).
  if (coverage > s.coverage || (coverage == s.coverage && (d < s.distance || (d == s.distance && t < s.t)))) {
    s.found = true;
    s.coverage = coverage;
    s.t = t;
    s.best_cut = near_start && started < 1.0f;
    s.time = leaf_time;
    s.cut = cut;
    s.cut_points = cut_points;
    s.u = u;
    s.distance = d;
    s.px = pc.x;
    s.py = pc.y;
    s.tx = tx;
    s.ty = ty;
    s.half_width = half_width;
    s.end_on = end_on;
  }
}

// Where in the footprint the segment lies: for each distinct piece, the points nearest to it, as
// many as its coverage is worth, on the strand's side of the segment's ends within reach. The
// pieces' coverages combine over the union of their points (overlaps count once).
CoverageMask fragment_mask(const DistanceState& s, const EndFalloff& ends, float& coverage) {
  FootprintAt f = s.footprint_at(s.t);
  if (f.binary) return kFullMask;
  FootprintSquare sq{f.ax_x, f.ax_y, f.ay_x, f.ay_y};
  const CoverageMask start_side =
      ends.start ? half_plane_mask(sq, ends.start_point.x, ends.start_point.y, ends.start_tx, ends.start_ty) : kFullMask;
  const CoverageMask end_side =
      ends.end ? half_plane_mask(sq, ends.end_point.x, ends.end_point.y, ends.end_tx, ends.end_ty) : kFullMask;
  constexpr int kPoints = kMaskSide * kMaskSide;
  CoverageMask all = 0;
  float total = 0;
  for (int i = 0; i < s.piece_count; ++i) {
    const auto& p = s.pieces[i];
    // The same rule as the coverage (distance_leaf): the end lines bound only the pieces they cut.
    CoverageMask allowed = kFullMask;
    if (p.cut_start) allowed &= start_side;
    if (p.cut_end) allowed &= end_side;
    int count = mask_points_for(p.coverage);
    CoverageMask m = nearest_points_mask(sq, p.px, p.py, -p.ty, p.tx, p.end_on, count, allowed,
                                         p.swept ? &p.sweep : nullptr);
    int k = mask_count(m);
    total += k > 0 ? p.coverage * float(mask_count(m & ~all)) / float(k) : p.coverage;
    all |= m;
  }
  // The points past the end lines, where they are not covered yet (distance_leaf).
  total += float(mask_count(s.beyond_ends & ~all)) / float(kPoints);
  all |= s.beyond_ends;
  coverage = std::clamp(std::max(total, s.coverage), 0.0f, 1.0f);
  return all;
}

// A segment shorter on the screen than it is wide (seen nearly end-on: the roots of hair at a
// head's crown, strands pointing at the camera) is no band across the footprint: on the screen
// it is a stub a fraction of its width long that turns sharply at its joints even where the strand
// bends a little, so they are left uncut and its band runs on across the footprint (the scalp's
// crown: alpha 0.75 where the strands cover 0.52). Such a segment is measured as the exact
// intersector sees it (ribbon_covers_point) at the footprint's 8 x 8 mask points: its mask is the
// points it covers, its coverage their share (a 16 x 16 grid was no closer on the scalp and the
// fur ball, and made thumbnails 20 % slower). Depth and shading point stay the leaves'.
constexpr float kStubChordFraction = 1.0f;  // of the width: shorter chords on the screen are stubs
constexpr float kStubForeshortening = 0.5f;  // and shorter than this fraction of the chord in space

bool stub_coverage(const Vec3f cp[4], const float width[4], const DistanceState& s, bool compute_mask,
                   CurveFragmentHit& hit) {
  const FootprintAt f = s.footprint_at(hit.t);
  CoverageMask mask = 0;
  const float step = 1.0f / kMaskSide;
  for (int j = 0; j < kMaskSide; ++j)
    for (int i = 0; i < kMaskSide; ++i) {
      const float u = (float(i) + 0.5f) * step - 0.5f, v = (float(j) + 0.5f) * step - 0.5f;
      if (ribbon_covers_point(cp, width, u * f.ax_x + v * f.ay_x, u * f.ax_y + v * f.ay_y))
        mask |= CoverageMask{1} << (j * kMaskSide + i);
    }
  if (mask == 0) return false;
  hit.coverage = float(mask_count(mask)) / float(kMaskSide * kMaskSide);
  hit.mask = compute_mask ? mask : kFullMask;
  return true;
}

float half_max_width(const float width[4]) {
  return std::max(0.0f, 0.5f * std::max(std::max(width[0], width[1]), std::max(width[2], width[3])));
}

void distance_recursive(const Vec3f cp[4], const float width[4], float u0, float u1, int depth,
                        const EndFalloff& ends, DistanceState& s) {
  if (depth == 0) {
    distance_leaf(cp, width, u0, u1, ends, s);
    return;
  }
  Vec3f cp_split[7];
  float width_split[7];
  bezier_split_half(cp, cp_split);
  bezier_split_half(width, width_split);
  float u_mid = 0.5f * (u0 + u1);
  for (int half = 0; half < 2; ++half) {
    const Vec3f* sub_cp = cp_split + 3 * half;
    const float* sub_width = width_split + 3 * half;
    float hw = half_max_width(sub_width);
    if (!(hw > 0.0f)) continue;
    float z_hi = std::max(std::max(sub_cp[0].z, sub_cp[1].z), std::max(sub_cp[2].z, sub_cp[3].z));
    float z_lo = s.reach_grows ? z_hi
                               : std::min(std::min(sub_cp[0].z, sub_cp[1].z), std::min(sub_cp[2].z, sub_cp[3].z));
    // Cull with the half-width plus the largest footprint over the sub-curve's depth range.
    float margin = hw + s.motion + s.reach_over_depths(z_lo - hw - s.motion, z_hi + hw + s.motion);
    if (!bound_overlaps_ray(sub_cp, margin, s.depth_min, s.t_max * s.ray_length)) continue;
    if (s.behind_start(sub_cp, hw)) continue;
    distance_recursive(sub_cp, sub_width, half == 0 ? u0 : u_mid, half == 0 ? u_mid : u1, depth - 1, ends, s);
  }
}

// An end's half-plane only bounds the strand near the end: a curved segment can come back
// across the end's line far from it (a loop, a Catmull-Rom swing), where it must not be cut.
// Where the end is out of the footprint's reach, the footprint is wholly on one side of the
// end's line for a straight strand anyway, so skipping the fall-off there changes nothing.
inline bool end_within_reach(const Vec3f& end, float half_width, const DistanceState& s) {
  const float near = half_width + s.motion;
  return hypot2(end.x, end.y) <= near + s.reach_over_depths(end.z - near, end.z + near);
}


}  // namespace

SegmentEnds segment_ends(const CurveSet& set, size_t i) {
  SegmentEnds e;
  e.strand_start = set.strand_start(i);
  e.strand_end = set.strand_end(i);
  return e;
}

bool intersect_segment_distance(const CurveSet& set, size_t segment, const Ray& ray, const RayFootprint& footprint,
                                CoverageModel model, SegmentEnds ends, CurveFragmentHit& hit, bool compute_mask) {
  return intersect_segment_distance(set, segment, make_distance_ray(ray, footprint), model, ends, hit,
                                    compute_mask);
}

namespace {

// The segment of shape `cp` (world space); with `from` and `to`, moving linearly from `from` to
// `to` during the interval the ray sweeps, `cp` being its shape half-way, never farther than
// `motion` from it.
// [time_from, time_to] is the motion's part of the ray's stretch of the shutter, in the stretch's
// own time (0 to 1: the mask points' times); [shutter_from, shutter_to] the same in shutter time.
bool intersect_shape(const CurveSet& set, size_t segment, const Vec3f* cp, const Vec3f* from, const Vec3f* to,
                     float motion, float time_from, float time_to, float shutter_from, float shutter_to,
                     const DistanceRay& ray, CoverageModel model, SegmentEnds ends, CurveFragmentHit& hit,
                     bool compute_mask) {
  const float* width = set.widths(segment);
  float hw = half_max_width(width);
  if (!(hw > 0.0f)) return false;
  // The control points in the ray's frame: depth along the ray, and 2D across it.
  float z[4], a[4], b[4];
  for (int i = 0; i < 4; ++i) {
    Vec3f rel = cp[i] - ray.origin;
    z[i] = dot(rel, ray.dir);
    a[i] = dot(rel, ray.frame_x);
    b[i] = dot(rel, ray.frame_y);
  }
  // Depth rejection first (cheapest): the hull's depth range against the ray's interval.
  float z_hi = std::max(std::max(z[0], z[1]), std::max(z[2], z[3]));
  float z_lo = std::min(std::min(z[0], z[1]), std::min(z[2], z[3]));
  const float t_far = std::max(0.0f, (z_hi + hw + motion) / ray.ray_length);
  const float reach_far = ray.reach.grows()
                              ? ray.reach.at(t_far)
                              : ray.reach.max_over(std::max(0.0f, (z_lo - hw - motion) / ray.ray_length), t_far);
  const float margin = hw + motion + reach_far;
  if (z_hi + margin < ray.depth_min || z_lo - margin > ray.t_max * ray.ray_length) return false;
  // Turn the frame in its plane so that x runs along the projected chord: the hull is then thin
  // in y and its bound tight (Nakamaru & Ohno's frame). A chord seen end-on keeps the frame.
  float cx = a[3] - a[0], cy = b[3] - b[0];
  float chord_2d = std::sqrt(cx * cx + cy * cy);
  Vec3f chord = cp[3] - cp[0];
  float cos_r = 1.0f, sin_r = 0.0f;
  if (chord_2d > float(kParallelSine) * length(chord) && chord_2d > 0.0f) {
    cos_r = cx / chord_2d;
    sin_r = cy / chord_2d;
  }
  Vec3f ray_cp[4];
  for (int i = 0; i < 4; ++i) ray_cp[i] = {cos_r * a[i] + sin_r * b[i], -sin_r * a[i] + cos_r * b[i], z[i]};
  if (!bound_overlaps_ray(ray_cp, margin, ray.depth_min, ray.t_max * ray.ray_length)) return false;

  DistanceState s;
  s.frame_x = ray.frame_x * cos_r + ray.frame_y * sin_r;
  s.frame_y = ray.frame_y * cos_r - ray.frame_x * sin_r;
  s.ray_length = ray.ray_length;
  s.t_min = ray.t_min;
  s.t_max = ray.t_max;
  s.depth_min = ray.depth_min;
  if (ray.has_start) {
    s.has_start = true;
    const float n = length(ray.start.n);
    s.start_margin = ray.start.margin / n;
    s.start_normal = Vec3f{dot(ray.start.n, s.frame_x), dot(ray.start.n, s.frame_y), dot(ray.start.n, ray.dir)} / n;
    s.start_du = dot(ray.footprint->dox, ray.dir);
    s.start_dv = dot(ray.footprint->doy, ray.dir);
    s.start_depth_max = 0.5f * (std::abs(s.start_du) + std::abs(s.start_dv));
    if (s.behind_start(ray_cp, hw)) return false;
  }
  s.footprint = ray.footprint;
  s.model = model;
  s.oriented = set.oriented(segment);
  if (s.oriented) {
    s.normal0 = set.end_normal(segment, 0);
    s.normal1 = set.end_normal(segment, 1);
  }
  s.dir = ray.dir;
  s.reach = ray.reach;
  s.reach_grows = ray.reach.grows();
  MovingKeys keys;
  if (from && to) {
    // The interval's ends in the turned frame; the shape half-way is ray_cp.
    auto to_frame = [&](const Vec3f& p) {
      const Vec3f rel = p - ray.origin;
      return Vec3f{dot(rel, s.frame_x), dot(rel, s.frame_y), dot(rel, ray.dir)};
    };
    for (int i = 0; i < 4; ++i) {
      keys.from[size_t(i)] = to_frame(from[i]);
      keys.to[size_t(i)] = to_frame(to[i]);
      s.mid_cp[i] = ray_cp[i];
    }
    s.motion = motion;
    s.keys = &keys;
    s.time_from = time_from;
    s.time_to = time_to;
    s.shutter_from = shutter_from;
    s.shutter_to = shutter_to;
    s.ends_shutter = time_to >= 1.0f;
  }

  EndFalloff fall;
  float min_tangent = kEndOnTangentFraction * 2.0f * hw;
  fall.start_is_joint = !ends.strand_start;
  fall.end_is_joint = !ends.strand_end;
  if (ends.strand_start || ends.cut_joints) {
    Vec3f d0 = ray_cp[1] - ray_cp[0];
    if (length_squared(d0) == 0.0f) d0 = ray_cp[2] - ray_cp[0];
    fall.start = unit_2d(d0, min_tangent, fall.start_tx, fall.start_ty) && end_within_reach(ray_cp[0], hw, s);
    fall.start_point = ray_cp[0];
  }
  if (ends.strand_end || ends.cut_joints) {
    Vec3f d1 = ray_cp[2] - ray_cp[3];
    if (length_squared(d1) == 0.0f) d1 = ray_cp[1] - ray_cp[3];
    fall.end = unit_2d(d1, min_tangent, fall.end_tx, fall.end_ty) && end_within_reach(ray_cp[3], hw, s);
    fall.end_point = ray_cp[3];
  }

  // Refine until leaves are flat relative to max(width, footprint): far, sub-pixel hair needs no
  // leaves flatter than the footprint it is averaged over (curve-ray-tracing.md §6 case 2).
  float nearest_footprint = 2.0f * s.least_reach_over_depths(z_lo, z_hi);
  int depth = refinement_depth(ray_cp, std::max(2.0f * hw, nearest_footprint));
  distance_recursive(ray_cp, width, 0.0f, 1.0f, depth, fall, s);
  if (!s.found) return false;
  // Stubs are segments seen nearly end-on: short on the screen against their width and against
  // their own length (a thumbnail's segments are short on the screen too, seen side-on, and the
  // band describes them; measuring them all made 32x24 renders 3-5 times slower).
  if (ends.cut_joints && !s.oriented && !s.keys && chord_2d < kStubChordFraction * 2.0f * hw &&
      chord_2d < kStubForeshortening * length(chord) && !s.footprint_at(s.t).binary) {
    hit.t = s.t;
    hit.u = s.u;
    hit.distance = s.distance;
    return stub_coverage(ray_cp, width, s, compute_mask, hit);
  }
  hit.t = s.t;
  hit.time = s.time;
  // The best leaf within the end lines, plus what the leaves cover past them.
  hit.coverage = std::min(
      1.0f, std::max(s.coverage, s.best_within_ends + float(mask_count(s.beyond_ends)) / float(kMaskSide * kMaskSide)));
  hit.u = s.u;
  hit.distance = s.distance;
  hit.mask = compute_mask ? fragment_mask(s, fall, hit.coverage) : kFullMask;
  if (compute_mask && s.best_cut) {
    // Its points are where the strand is met, not the ones nearest its axis: strands of a clump
    // beside the start patch are all met on the same side of it, and nearest points cut there
    // spread the coverage they cannot hold over the other side (head-hair: shadows through the
    // crown's clumps twice as dark as the sub-rays find them).
    const CoverageMask started = s.cut_points != 0 ? s.cut_points : hit.mask & s.cut.mask();
    if (started != 0) hit.mask = started;
  }
  return true;
}

}  // namespace

bool intersect_segment_distance(const CurveSet& set, size_t segment, const DistanceRay& ray, CoverageModel model,
                                SegmentEnds ends, CurveFragmentHit& hit, bool compute_mask) {
  if (!ray.valid) return false;
  if (!ray.sweeps_shutter || !set.moving(segment)) {
    Vec3f at_time[4];
    const Vec3f* cp = set.control_points_at(segment, ray.time, at_time);
    return intersect_shape(set, segment, cp, nullptr, nullptr, 0.0f, 0.0f, 1.0f, 0.0f, 1.0f, ray, model, ends, hit,
                           compute_mask);
  }
  // A ray sweeping a stretch [a, b] of the shutter: each part of it between the segment's keys
  // (along which its points move linearly) in closed form, weighted by its share of the stretch.
  // The best part gives the depth and shading parameter, the masks add up (their points' times
  // are those of the stretch, mask_point_time scaled to it).
  const SegmentMotion& m = set.motions[set.motion[segment]];
  const float* times = set.motion_times.data() + m.times;
  const Vec3f* key_cp = set.motion_cp.data() + m.points;
  const float a = ray.sweep_from, b = ray.sweep_to, length_ab = b - a;
  if (!(length_ab > 0.0f)) {
    Vec3f at_time[4];
    const Vec3f* cp = set.control_points_at(segment, ray.time, at_time);
    return intersect_shape(set, segment, cp, nullptr, nullptr, 0.0f, 0.0f, 1.0f, 0.0f, 1.0f, ray, model, ends, hit,
                           compute_mask);
  }
  float total = 0, best = -1;
  CoverageMask mask = 0;
  for (uint32_t k = 0; k + 1 < m.keys; ++k) {
    const float lo = std::max(a, times[k]), hi = std::min(b, times[k + 1]);
    if (!(hi > lo)) continue;
    const float span = times[k + 1] - times[k];
    const Vec3f* key_from = key_cp + k * kControlPointsPerSegment;
    const Vec3f* key_to = key_from + kControlPointsPerSegment;
    // The segment at the part's ends and half-way.
    Vec3f from[4], to[4], middle[4];
    const float s_lo = (lo - times[k]) / span, s_hi = (hi - times[k]) / span;
    float motion = 0.0f;
    for (size_t j = 0; j < kControlPointsPerSegment; ++j) {
      from[j] = s_lo == 0.0f ? key_from[j] : lerp(s_lo, key_from[j], key_to[j]);
      to[j] = s_hi == 1.0f ? key_to[j] : lerp(s_hi, key_from[j], key_to[j]);
      middle[j] = lerp(0.5f, from[j], to[j]);
      motion = std::max(motion, 0.5f * length(to[j] - from[j]));
    }
    motion *= 1.0f + 1e-5f;  // the rounding of the middle
    const float share = (hi - lo) / length_ab;
    CurveFragmentHit h;
    if (!intersect_shape(set, segment, middle, from, to, motion, (lo - a) / length_ab, (hi - a) / length_ab, lo, hi,
                         ray, model, ends, h, compute_mask))
      continue;
    total += share * h.coverage;
    mask |= h.mask;
    if (share * h.coverage > best) {
      best = share * h.coverage;
      hit = h;
    }
  }
  if (!(total > 0.0f)) return false;
  hit.coverage = std::min(1.0f, total);
  hit.mask = compute_mask ? mask : kFullMask;
  return true;
}

}  // namespace darc
