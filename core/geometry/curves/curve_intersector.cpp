#include "core/geometry/curves/curve_intersector.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/math/curve_basis.h"
#include "core/geometry/curves/curve_ray_space.h"

namespace darc {

namespace {

// What the recursion needs besides the (sub)curve: the ray interval and the ribbon orientation.
struct TraversalState {
  float ray_length;  // |d|: ray-space z is t * |d|
  float t_min;       // hits need t in (t_min, t_best)
  float t_best;      // shrinks as nearer hits are found
  bool oriented;
  Vec3f normal0, normal1;  // world-space end normals of an oriented ribbon
  Vec3f dir;               // world-space unit ray direction
  // The nearest leaf hit so far.
  bool found = false;
  float u = 0;
  float signed_offset = 0;  // from the curve axis to the ray, across the ribbon
  float half_width = 0;
};

// Half of the largest width coefficient: the Bézier width (and the oriented width, scaled by a
// cosine <= 1) never exceeds it, so it bounds the ribbon around its axis. The distance-aware
// variant will add the ray footprint radius here.
// Zero when the whole (sub)curve is hidden.
float cull_margin(const float width[4]) {
  return std::max(0.0f, 0.5f * std::max(std::max(width[0], width[1]), std::max(width[2], width[3])));
}

// The oriented-ribbon factor: the ribbon seen at a grazing angle is narrower.
float orientation_scale(const TraversalState& s, float u) {
  if (!s.oriented) return 1.0f;
  Vec3f n = normalize(lerp(u, s.normal0, s.normal1));
  if (length_squared(n) == 0.0f) n = s.normal0;  // opposite end normals: keep the first
  return std::abs(dot(n, s.dir));
}

// Tests one (nearly straight) leaf covering [u0, u1] of the segment; updates `s` with a nearer hit.
void intersect_leaf(const Vec3f cp[4], const float width[4], float u0, float u1, TraversalState& s) {
  float chord_x = cp[3].x - cp[0].x, chord_y = cp[3].y - cp[0].y;
  float chord_length2 = chord_x * chord_x + chord_y * chord_y;
  float point_chord = kPointChordFraction * 2.0f * cull_margin(width);
  float w;
  if (chord_length2 <= point_chord * point_chord) {
    // Seen end-on: the leaf is a point; its nearer end is what the ray meets first.
    w = cp[0].z <= cp[3].z ? 0.0f : 1.0f;
  } else {
    // The ray (the origin) must lie between the planes perpendicular to the curve at the leaf's
    // ends, so that neighbouring leaves neither overlap nor leave gaps on straight parts.
    if ((cp[1].x - cp[0].x) * -cp[0].x + (cp[1].y - cp[0].y) * -cp[0].y < 0.0f) return;
    if ((cp[2].x - cp[3].x) * -cp[3].x + (cp[2].y - cp[3].y) * -cp[3].y < 0.0f) return;
    w = (-cp[0].x * chord_x - cp[0].y * chord_y) / chord_length2;
  }
  w = std::clamp(w, 0.0f, 1.0f);
  float u = std::clamp(u0 + (u1 - u0) * w, u0, u1);
  float half_width = 0.5f * bezier_evaluate(width, w) * orientation_scale(s, u);
  if (!(half_width > 0.0f)) return;  // the hidden (negative-width) part of a strand
  Vec3f pc = bezier_evaluate(cp, w);
  float distance2 = pc.x * pc.x + pc.y * pc.y;
  if (distance2 > half_width * half_width) return;
  float t = pc.z / s.ray_length;
  if (!(t > s.t_min && t < s.t_best)) return;
  // Sign: which side of the projected tangent the ray passes (towards cross(d, tangent)).
  Vec3f tangent = bezier_derivative(cp, w);
  float side = pc.x * tangent.y - pc.y * tangent.x;
  float distance = std::sqrt(distance2);
  s.found = true;
  s.t_best = t;
  s.u = u;
  s.signed_offset = side < 0.0f ? -distance : distance;
  s.half_width = half_width;
}

// Splits at the middle until the depth is used up, testing BOTH halves so that the nearest hit
// wins on curves that overlap themselves along the ray (a first-found rule returns the far loop).
void intersect_recursive(const Vec3f cp[4], const float width[4], float u0, float u1, int depth, TraversalState& s) {
  if (depth == 0) {
    intersect_leaf(cp, width, u0, u1, s);
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
    // t_best shrinks after a hit in the first half, so the second is culled against it.
    float z_lo = s.t_min * s.ray_length, z_hi = s.t_best * s.ray_length;
    float margin = cull_margin(sub_width);
    if (!(margin > 0.0f) || !bound_overlaps_ray(sub_cp, margin, z_lo, z_hi)) continue;
    intersect_recursive(sub_cp, sub_width, half == 0 ? u0 : u_mid, half == 0 ? u_mid : u1, depth - 1, s);
  }
}

}  // namespace

bool ribbon_covers_point(const Vec3f cp[4], const float width[4], float x, float y) {
  Vec3f shifted[4];
  for (int i = 0; i < 4; ++i) shifted[i] = {cp[i].x - x, cp[i].y - y, cp[i].z};
  TraversalState s{};
  s.ray_length = 1.0f;
  s.t_min = -std::numeric_limits<float>::infinity();
  s.t_best = std::numeric_limits<float>::infinity();
  s.oriented = false;
  intersect_recursive(shifted, width, 0.0f, 1.0f, refinement_depth(shifted, 2.0f * cull_margin(width)), s);
  return s.found;
}

namespace {

bool is_finite(const Vec3f& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// A unit tangent at u: the derivative, else the chord (coincident control points), else any
// direction perpendicular to the ray.
Vec3f world_tangent(const Vec3f cp[4], float u, const Vec3f& dir) {
  Vec3f tangent = normalize(bezier_derivative(cp, u));
  if (length_squared(tangent) == 0.0f) tangent = normalize(cp[3] - cp[0]);
  if (length_squared(tangent) == 0.0f) {
    Vec3f unused;
    orthonormal_basis(dir, tangent, unused);
  }
  return tangent;
}

// The ribbon normal at the hit, turned towards the ray origin.
Vec3f world_normal(const TraversalState& s, const Vec3f& tangent) {
  Vec3f n;
  if (s.oriented) {
    n = normalize(lerp(s.u, s.normal0, s.normal1));
    if (length_squared(n) == 0.0f) n = s.normal0;
  } else {
    // Facing the ray: the part of -d perpendicular to the tangent.
    n = normalize(-s.dir + tangent * dot(s.dir, tangent));
  }
  if (length_squared(n) == 0.0f) n = -s.dir;  // ray along the tangent
  return dot(n, s.dir) > 0.0f ? -n : n;
}

}  // namespace

bool intersect_segment(const CurveSet& set, size_t segment, const Ray& ray, CurveHit& hit) {
  Vec3f at_time[4];
  const Vec3f* cp = set.control_points_at(segment, ray.time, at_time);
  const float* width = set.widths(segment);
  float margin = cull_margin(width);
  if (!(margin > 0.0f)) return false;  // hidden everywhere
  if (!is_finite(ray.o) || !is_finite(ray.d) || std::isnan(ray.tmin) || std::isnan(ray.tmax)) return false;
  if (!bounding_sphere_may_hit(cp, margin, ray)) return false;
  Vec3d dir(ray.d);
  double ray_length = length(dir);
  if (!(ray_length > 0.0)) return false;
  dir = dir / ray_length;

  // Control points relative to the ray origin, in double: far from the world origin (1e5) the
  // float differences would lose the width.
  Vec3d origin(ray.o);
  Vec3d rel[4];
  for (int i = 0; i < 4; ++i) rel[i] = Vec3d(cp[i]) - origin;
  RayFrame frame = make_ray_frame(dir, rel[3] - rel[0]);
  Vec3f ray_cp[4];
  for (int i = 0; i < 4; ++i) ray_cp[i] = frame.to_ray_space(rel[i]);

  TraversalState s;
  s.ray_length = static_cast<float>(ray_length);
  s.t_min = ray.tmin;
  s.t_best = ray.tmax;
  s.oriented = set.oriented(segment);
  if (s.oriented) {
    s.normal0 = set.end_normal(segment, 0);
    s.normal1 = set.end_normal(segment, 1);
  }
  s.dir = Vec3f(dir);
  if (!bound_overlaps_ray(ray_cp, margin, s.t_min * s.ray_length, s.t_best * s.ray_length)) return false;
  intersect_recursive(ray_cp, width, 0.0f, 1.0f, refinement_depth(ray_cp, 2.0f * margin), s);
  if (!s.found) return false;

  hit.t = s.t_best;
  hit.u = s.u;
  hit.v = std::clamp(s.signed_offset / s.half_width, -1.0f, 1.0f);
  hit.p = ray.at(s.t_best);
  hit.tangent = world_tangent(cp, s.u, s.dir);
  hit.normal = world_normal(s, hit.tangent);
  return true;
}

}  // namespace darc
