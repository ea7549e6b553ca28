// The state of one ray's distance test against one curve segment (curve_distance_intersector.cpp):
// the footprint in the ray's frame at a depth, a moving segment's keys, and the best fragment and
// pieces found so far. Internal to the distance intersector, split out of it to keep its files
// readable; everything is inline, so the intersector compiles as one unit as before.
#pragma once

#include "core/footprint/coverage_mask.h"
#include "core/footprint/start_cut.h"
#include "core/footprint/swept_coverage.h"
#include "core/geometry/curves/curve_distance_intersector.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

namespace darc::curve_distance {

// sqrt(x^2 + y^2) without hypot's overflow care (libm's hypotf is a call and several times
// slower; ray-space coordinates are far from float's range limits).
inline float hypot2(float x, float y) { return std::sqrt(x * x + y * y); }

// Leaves whose projected directions are within about 30 degrees are one piece of the strand.
constexpr float kDistinctPieceCos = 0.866f;
// The fan of a segment past its end lines (leaf_beyond_ends) lies within its half-width of the
// strand, an area of order half-width squared; it is counted by mask points only where the
// half-width is at least this many footprint sides. Narrower, the fan is a few of the 64 points
// at most, each worth 1/64 of the footprint, so counting them adds as much noise as it removes:
// measured on HardCases.VeryThinFarStrands (strands 1/20 of the footprint, +0.6 % of the total
// alpha) and on the furball benchmark (8 footprints with 1 to 3 points, 1x1 RMSE +0.02 %).
constexpr float kMinFanHalfWidthInFootprints = 1.0f;
// Projected tangents shorter than this fraction of the width are "seen end-on": the strand's
// end has no direction on screen and gets no end fall-off.
constexpr float kEndOnTangentFraction = 1e-3f;

// The footprint in ray space (x, y of the ray frame) at one depth, and how it turns a distance
// into coverage.
struct FootprintAt {
  float ax_x, ax_y, ay_x, ay_y;  // the two axes, projected onto the ray frame's xy plane
  float r_box, r_disc;           // the radii of the box (seed) and disc forms
  bool binary;                   // no footprint: coverage is a hit test

  // Marginal widths of the square footprint along a unit 2D direction (nx, ny).
  void square_extents(float nx, float ny, float& a, float& b) const {
    a = std::abs(ax_x * nx + ax_y * ny);
    b = std::abs(ay_x * nx + ay_y * ny);
  }
};

// A moving segment over one interval between its keys, in the ray's frame (turned along the
// chord): its control points at the interval's start and end (the shape the leaves see is the
// one half-way).
struct MovingKeys {
  std::array<Vec3f, 4> from, to;
};

struct DistanceState {
  float ray_length;
  float t_min, t_max;
  float depth_min;  // DistanceRay::depth_min
  // DistanceRay::start: whether the sub-rays start on a plane leaning along the ray, then a leaf
  // at any depth may be ahead of some of them (StartCut decides); else ahead means past t_min.
  bool has_start = false;
  float start_margin = 0;
  Vec3f start_normal;  // unit, in this frame, toward where the sub-rays go
  // Whether a (sub-)curve of half-width hw lies wholly behind the start plane: no sub-ray meets it.
  bool behind_start(const Vec3f cp[4], float hw) const {
    if (!has_start) return false;
    for (int i = 0; i < 4; ++i)
      if (!(dot(start_normal, cp[i]) < -hw)) return false;
    return true;
  }
  bool ahead(float t) const { return t < t_max && (has_start || t > t_min); }
  // With a start half-space, the depth of sub-ray (u, v)'s origin is u start_du + v start_dv
  // (the start patch leans along the ray): only the sub-rays that start before a strand meet it.
  float start_du = 0, start_dv = 0;
  float start_depth_max = 0;  // the farthest origin's depth
  bool best_cut = false;  // whether the best leaf is cut (cut below)
  StartCut cut;  // the sub-rays that start before the best leaf where they cross it
  CoverageMask cut_points = 0;  // the best leaf's band points that are cut (none: a band too thin)
  const RayFootprint* footprint;
  Vec3f frame_x, frame_y;  // the ray frame, its x axis along the segment's projected chord
  CoverageModel model;
  bool oriented;
  Vec3f normal0, normal1, dir;
  ReachBound reach;  // the footprint's reach at ray parameter t
  bool reach_grows = true;  // reach.grows(): a depth range's largest reach is at its far end
  // Motion blur, for a ray that sweeps the shutter past a moving segment: the segment is the one
  // at the ray's time (the control points the leaves see), and comes within `motion` of its
  // shape then at other times. Its keys in this frame give how far each point moves across a
  // leaf's band (swept_band_coverage).
  float motion = 0;
  const MovingKeys* keys = nullptr;
  float time_from = 0, time_to = 1;  // the keys' interval, in the ray's stretch's time (masks)
  float shutter_from = 0, shutter_to = 1;  // the same in shutter time (shading)
  bool ends_shutter = false;         // the last interval (its mask points' times include 1)
  float time = -1;                   // the best leaf's: when it passes the centre (-1: the ray's)
  Vec3f mid_cp[4];  // the segment half-way through the interval, in this frame
  // Best fragment so far, and the geometry its coverage mask needs.
  bool found = false;
  float coverage = 0, t = 0, u = 0, distance = 0;
  float px = 0, py = 0, tx = 1, ty = 0, half_width = 0;
  bool end_on = false;
  // The footprint points the strand covers past the segment's end lines (the wings where the
  // leaves' slabs fan out past them, distance_leaf), over all leaves, and the best coverage of
  // a leaf within the end lines, which they add to.
  CoverageMask beyond_ends = 0;
  float best_within_ends = 0;
  // The distinct pieces of the segment near the ray: leaves whose directions differ by more than
  // kDistinctPieceCos (a hairpin's two legs, a kink) cover different parts of the footprint and
  // are combined through their masks; similar leaves are the same piece (the best one counts).
  struct Piece {
    float coverage, px, py, tx, ty, half_width;
    bool end_on;
    bool cut_start, cut_end;  // whether the segment's end lines bound this piece (distance_leaf)
    bool swept = false;       // moving during [time_from, time_to): its line moves by `sweep`
    SweptLine sweep;
  };
  std::array<Piece, 4> pieces{};
  int piece_count = 0;

  void add_piece(const Piece& p) {
    for (int i = 0; i < piece_count; ++i)
      if (pieces[i].tx * p.tx + pieces[i].ty * p.ty > kDistinctPieceCos) {
        if (p.coverage > pieces[i].coverage) pieces[i] = p;
        return;
      }
    if (piece_count < int(pieces.size())) pieces[piece_count++] = p;
  }

  // The largest reach over the depths [z0, z1] along the unit direction (none before the origin).
  float reach_over_depths(float z0, float z1) const {
    if (reach_grows) return reach.at(std::max(0.0f, z1 / ray_length));
    return reach.max_over(std::max(0.0f, z0 / ray_length), std::max(0.0f, z1 / ray_length));
  }
  // The smallest: at the depth of the interval nearest the apex (the V's minimum).
  float least_reach_over_depths(float z0, float z1) const {
    const float t0 = std::max(0.0f, z0 / ray_length);
    if (reach_grows) return reach.at(t0);
    const float t1 = std::max(t0, z1 / ray_length);
    return reach.at(std::clamp(reach.apex_t, t0, t1));
  }

  FootprintAt footprint_at(float t_hit) const {
    FootprintAt f;
    Vec3f ax = footprint->axis_x(t_hit), ay = footprint->axis_y(t_hit);
    f.ax_x = dot(ax, frame_x);
    f.ax_y = dot(ax, frame_y);
    f.ay_x = dot(ay, frame_x);
    f.ay_y = dot(ay, frame_y);
    float lx = hypot2(f.ax_x, f.ax_y), ly = hypot2(f.ay_x, f.ay_y);
    // The box form's radius is half the sample spacing; the disc has the square's area.
    f.r_box = std::max(0.25f * (lx + ly), footprint->min_radius);
    f.r_disc = std::max(std::sqrt(lx * ly / std::numbers::pi_v<float>), footprint->min_radius);
    f.binary = !(lx + ly > 2.0f * footprint->min_radius);
    return f;
  }
};

}  // namespace darc::curve_distance
