// A partial hit of one ray of the distance-aware hider (integrator/abuffer.h collects them):
// where in the footprint it lies, how much of it it covers, and where it is shaded.
#pragma once

#include "core/footprint/coverage_mask.h"
#include "core/geometry/curves/curve_set.h"
#include "core/geometry/surfaces/surface_set.h"
#include "core/math/vec.h"

#include <array>
#include <cstdint>

namespace darc {

// The depth of a plane along the footprint's sub-rays, to first order about the footprint's
// centre: t(u, v) = t0 + du u + dv v. Not `valid` where the plane is seen edge-on.
// A weight per footprint point (8 x 8, the mask's order).
using FootprintPointWeights = std::array<float, kMaskSide * kMaskSide>;

struct DepthPlane {
  float t0 = 0, du = 0, dv = 0;
  bool valid = false;
  float at(float u, float v) const { return t0 + du * u + dv * v; }
};

struct Fragment {
  float t = 0;
  float coverage = 1;        // fraction of the footprint covered
  uint32_t strand = kNoStrand;  // curve strand id; kNoStrand for surfaces
  uint32_t primitive = 0;    // grid primitive index (what to shade)
  float u = 0;               // along the curve segment (curves only)
  float time = -1;           // a moving strand's shading time (CurveFragmentHit::time; -1: the ray's)
  // Set when two fragments were merged because the list was full: their light and opacity
  // are then already shaded, per footprint point, in the A-buffer's merged record `merged`.
  bool preshaded = false;
  int merged = -1;
  // Where in the footprint the fragment lies (8 x 8 points); the scalar coverage says how much.
  CoverageMask mask = kFullMask;
  // Surfaces: the footprint point whose sub-ray hit is shaded (-1: the ray itself).
  int surface_point = -1;
  // Curves: from the ray to the strand axis at the shading point. Decides which of a strand's
  // equally covering pieces is shaded: the nearest is where the strand's closest approach is.
  float distance = 0;
  // Surfaces with analytic coverage: shaded where the sub-ray (sub_u, sub_v) meets them (the
  // centroid of what they cover).
  bool at_sub_ray = false;
  float sub_u = 0, sub_v = 0;
  // Strands shaded where they are seen (at_sub_ray): the share of the strand's coverage that is
  // (its shadow rays leave a band that much narrower than the strand).
  float seen_share = 1;
  // Surfaces shaded where they are seen (ABuffer::at_visible_part): the footprint point
  // (depth_u, depth_v) at which t is the depth (the one at (sub_u, sub_v) is on the plane through
  // it with `normal`), and the part of the footprint, patch_u x patch_v around (sub_u, sub_v),
  // that is the surface seen there (its shadow rays leave from that patch).
  bool moved = false;
  float depth_u = 0, depth_v = 0;
  float patch_u = 1, patch_v = 1;
  // Pieces of one surface (a mesh's triangles or faces): its layer key (kNoLayer: none) and the
  // depth range of what the piece covers. Pieces of one layer whose ranges meet are one
  // fragment: their coverages are areas of a partition and add up, their masks unite.
  uint32_t layer = kNoLayer;
  float t_near = 0, t_far = 0;
  // Layer pieces: the piece's geometric normal; and, once pieces facing apart (a fold, a
  // crease, a silhouette's turn) are in one fragment, the index of its shading sites in the
  // A-buffer (-1: shaded at its own primitive and sub-ray alone).
  Vec3f normal{};
  int sites = -1;
  bool covers_centre = false;  // the piece holds the footprint's centre (and is shaded there)
  bool planar = false;         // a planar piece (a polygon, a mesh face, a triangle)
  // Layer pieces: the depth of the piece's plane over the footprint, linear in the footprint's
  // coordinates (DepthPlane): which of two overlapping pieces of one layer is in front.
  DepthPlane plane{};
};

}  // namespace darc
