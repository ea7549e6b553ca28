// The distance-aware hider (Nakamaru, Matsuoka & Fujita 2012): each camera ray carries a
// footprint from its ray differentials; the grid is traversed with that footprint; curves
// return their distance to the ray, turned into coverage; partial hits go into an A-buffer that
// is composited front to back; traversal stops once the remaining transmittance is negligible.
// Surfaces (spheres, polygons) enter the same list as opaque fragments with exact hit tests, so
// --pixel-samples N also antialiases their edges.
#pragma once

#include "core/footprint/coverage.h"
#include "core/geometry/curves/curve_distance_intersector.h"
#include "integrator/abuffer.h"
#include "integrator/hit_filter.h"
#include "integrator/ray_scratch.h"
#include "integrator/secondary_rays.h"
#include "core/math/bbox.h"
#include "core/footprint/coverage_mask.h"
#include "core/geometry/surfaces/surface_hit.h"
#include "integrator/stochastic_hider.h"

#include <array>
#include <limits>

#include <vector>

namespace darc {

// Remaining transmittance below which a ray stops: what is behind can change the pixel by at
// most this fraction (curve-ray-tracing.md §6 case 8 suggests 1e-3).
inline constexpr float kDistanceMinTransmittance = 1e-3f;
// Traversal steps (grid layers, BVH nodes) between two sorts-and-composites of the A-buffer:
// the seed's 5. Fewer sorts cost less; more frequent ones terminate opaque rays earlier
// (docs/performance.md measures 1-10 on the grid). A composite only happens when a pending
// fragment has become final, so with the BVH (a step per node) the interval matters less.
inline constexpr int kDefaultSortInterval = 5;

struct DistanceHiderSettings {
  CoverageModel coverage = CoverageModel::Square;
  int sort_interval = kDefaultSortInterval;
  // Composite with 8x8 coverage masks (where each strand lies in the footprint) instead of
  // scalar coverage alone: removes the uncorrelated-overlap bias (docs/performance.md).
  bool coverage_masks = true;
  // Motion blur: every ray is traced once per stretch of the shutter, this many equal stretches,
  // and averaged. Strands that pass in front of one another during the shutter are composited in
  // their order at each stretch's middle, and coverages of one stretch as if independent in time:
  // on the swinging tuft (bench, --size blur) one stretch gave RMSE 0.0046, two 0.0030, four
  // 0.0022 (the reference's own noise about 0.0015).
  int time_strata = 4;
  // Area lights (rect, disc, sphere) cast one cone shadow ray per shading point, whose footprint
  // grows from the receiving patch to the light's extent, instead of one shadow ray per light
  // sample (--area-shadows sampled turns it off).
  bool area_light_cones = true;
};

// Per-frame data the distance hider needs besides the HiderContext.
struct DistanceContext {
  const HiderContext& base;
  DistanceHiderSettings settings;
  float min_radius;               // footprint floor (scene-scale relative)
};

DistanceContext make_distance_context(const HiderContext& base, const DistanceHiderSettings& settings);

// The ray through footprint point `point` of the 8 x 8 mask grid (its differentials applied).
Ray footprint_sub_ray(const Ray& ray, const RayFootprint& footprint, int point);
// The sub-ray at footprint coordinates (u, v) in [-1/2, 1/2]^2.
Ray footprint_sub_ray_at(const Ray& ray, const RayFootprint& footprint, float u, float v);

// Surfaces are antialiased with the same footprint: a surface whose edge crosses the footprint
// covers the mask points whose sub-rays hit it. The ray itself and the four corner points are
// tried first; when all five hit, the surface covers the footprint (exact for convex shapes; a
// hole smaller than the footprint between the five points is missed), when none does, it is
// taken to miss it (a surface smaller than the footprint between them is missed) unless it is a
// piece of a tessellated surface or mesh (`piece_bounds`, its box): pieces are often smaller than
// the footprint, and a mesh of them must cover every point a sub-ray of it hits, so they are
// tried at every mask point their box can reach (footprint_cells) when the five do not all hit.
struct SurfaceFragment {
  float t = 0;
  float coverage = 0;
  CoverageMask mask = 0;
  int point = -1;  // the sub-ray whose hit is shaded (-1: the ray itself)
  // When the surface covers the whole footprint: its depths at the four corner mask points
  // (columns 0 and 7 of rows 0 and 7, in that order), for a surface whose depth changes much
  // across the footprint (split_by_depth).
  bool whole = false;
  std::array<float, 4> corner_t{};
};

// The rectangle of footprint mask points [col0, col1] x [row0, row1] whose sub-rays can meet
// the box `bounds`: its corners projected into the footprint's (u, v) at their depths along the
// ray, widened by kPieceCellMargin cells for the footprint's curvature across the box. The whole
// grid when that cannot be known (a corner behind the ray's origin, degenerate axes).
struct FootprintCells {
  int col0 = 0, col1 = kMaskSide - 1, row0 = 0, row1 = kMaskSide - 1;
  bool empty() const { return col0 > col1 || row0 > row1; }
  bool whole() const { return col0 == 0 && row0 == 0 && col1 == kMaskSide - 1 && row1 == kMaskSide - 1; }
};
// The projection is exact to first order in the footprint's size; one cell more on each side
// covers the rest for any footprint the hiders make (spreads up to 0.15 rad, ray_differentials.cpp).
inline constexpr float kPieceCellMargin = 1.0f;
FootprintCells footprint_cells(const Ray& ray, const RayFootprint& footprint, const BBox& bounds);

template <class HitSurface>
bool surface_coverage(const Ray& ray, const RayFootprint& footprint, HitSurface&& hit_surface, SurfaceFragment& out,
                      const BBox* piece_bounds = nullptr) {
  SurfaceHit h;
  constexpr int kLast = kMaskSide * kMaskSide - 1;
  // A piece of a tessellated surface is tried at the mask points its box can reach, only.
  const FootprintCells cells = piece_bounds && footprint.has_differentials()
                                   ? footprint_cells(ray, footprint, *piece_bounds)
                                   : FootprintCells{};
  if (cells.empty()) return false;
  const bool piece = piece_bounds != nullptr;
  bool centre = false;
  float centre_t = 0;
  if (cells.whole() || !piece) {
    centre = hit_surface(ray, h);
    centre_t = h.t;
    if (!footprint.has_differentials()) {
      if (!centre) return false;
      out = {centre_t, 1.0f, kFullMask, -1};
      return true;
    }
    const int corners[4] = {0, kMaskSide - 1, kLast - (kMaskSide - 1), kLast};
    int corner_hits = 0;
    std::array<float, 4> corner_t{};
    for (int k = 0; k < 4; ++k)
      if (hit_surface(footprint_sub_ray(ray, footprint, corners[k]), h)) {
        ++corner_hits;
        corner_t[size_t(k)] = h.t;
      }
    if (centre && corner_hits == 4) {
      out = {centre_t, 1.0f, kFullMask, -1};
      out.whole = true;
      out.corner_t = corner_t;
      return true;
    }
    if (!centre && corner_hits == 0 && !piece) return false;
  }
  CoverageMask mask = 0;
  float nearest_t = std::numeric_limits<float>::infinity();
  int nearest_point = -1;
  for (int row = cells.row0; row <= cells.row1; ++row)
    for (int col = cells.col0; col <= cells.col1; ++col) {
      const int b = row * kMaskSide + col;
      if (!hit_surface(footprint_sub_ray(ray, footprint, b), h)) continue;
      mask |= CoverageMask{1} << b;
      if (h.t < nearest_t) {
        nearest_t = h.t;
        nearest_point = b;
      }
    }
  if (mask == 0) return false;
  out.mask = mask;
  out.coverage = float(mask_count(mask)) / float(kLast + 1);
  out.t = centre ? centre_t : nearest_t;
  out.point = centre ? -1 : nearest_point;
  return true;
}

// The colour, alpha and depth seen by one ray with footprint `footprint`: a camera ray, or a
// reflected or refracted one (`path` says where it is on its path, `filter` what it leaves).
// Its shading casts shadow, reflected and refracted rays through the same footprint walk and
// A-buffer, with the next levels of `scratch`.
SampleValue trace_distance_ray(const DistanceContext& ctx, const Ray& ray, const RayFootprint& footprint,
                               RayCounters& counters, RayScratchStack& scratch, const PathState& path = {},
                               const HitFilter& filter = {});

// The transmittance of the footprint along `ray` (mean over its 8x8 points): every strand and
// surface it passes, front to back, as coverage x opacity, through the same walk and A-buffer as
// camera rays (so thin strands attenuate smoothly); stops once below `min_transmittance`.
// Hits `filter` skips are left out (the strand or surface a shadow ray starts on); each primitive
// blocks by its Transmission attribute (shadow_opacity). Opacity is the primitive's Os: shaders
// that change Oi are not consulted.
// With `point_weights`, the transmittance is their weighted mean over the footprint's points
// instead (the points of a receiving patch where the receiver is seen).
Vec3f trace_footprint_transmittance(const DistanceContext& ctx, const Ray& ray, const RayFootprint& footprint,
                                    RayCounters& counters, RayScratch& scratch, const HitFilter& filter,
                                    float min_transmittance = kDistanceMinTransmittance,
                                    const FootprintPointWeights* point_weights = nullptr);
// The same, leaving out strand `skip_strand` only (kNoStrand: none).
Vec3f trace_footprint_transmittance(const DistanceContext& ctx, const Ray& ray, const RayFootprint& footprint,
                                    RayCounters& counters, RayScratch& scratch, uint32_t skip_strand);

// Renders the samples of the pixels in `rect`: N x N rays per pixel through the centres of the
// strata, each with a footprint of 1/N of a pixel.
void render_tile_distance(const DistanceContext& ctx, const PixelRect& rect, TileAccumulator& acc,
                          RayCounters& counters);

}  // namespace darc
