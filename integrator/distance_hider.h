// The distance-aware hider (Nakamaru, Matsuoka & Fujita 2012): each camera ray carries a
// footprint from its ray differentials; the grid is traversed with that footprint; curves
// return their distance to the ray, turned into coverage; partial hits go into an A-buffer that
// is composited front to back; traversal stops once the remaining transmittance is negligible.
// Surfaces (spheres, polygons) enter the same list as opaque fragments with exact hit tests, so
// --pixel-samples N also antialiases their edges.
#pragma once

#include "core/coverage.h"
#include "core/curve_distance_intersector.h"
#include "integrator/abuffer.h"
#include "integrator/stochastic_hider.h"

#include <vector>

namespace darc {

// Remaining transmittance below which a ray stops: what is behind can change the pixel by at
// most this fraction (curve-ray-tracing.md §6 case 8 suggests 1e-3).
inline constexpr float kDistanceMinTransmittance = 1e-3f;
// Traversal steps (grid layers) between two sorts-and-composites of the A-buffer: the seed's
// 5. Fewer sorts cost less; more frequent ones terminate opaque rays earlier
// (docs/performance.md measures 1-10).
inline constexpr int kDefaultSortInterval = 5;

struct DistanceHiderSettings {
  CoverageModel coverage = CoverageModel::Square;
  int sort_interval = kDefaultSortInterval;
  // Composite with 8x8 coverage masks (where each strand lies in the footprint) instead of
  // scalar coverage alone: removes the uncorrelated-overlap bias (docs/performance.md).
  bool coverage_masks = true;
};

// Per-frame data the distance hider needs besides the HiderContext.
struct DistanceContext {
  const HiderContext& base;
  DistanceHiderSettings settings;
  std::vector<SegmentEnds> ends;  // per curve segment
  float min_radius;               // footprint floor (scene-scale relative)
};

DistanceContext make_distance_context(const HiderContext& base, const DistanceHiderSettings& settings);

// The colour, alpha and depth seen by one camera ray with footprint `footprint`.
SampleValue trace_distance_ray(const DistanceContext& ctx, const Ray& ray, const RayFootprint& footprint,
                               RayCounters& counters, Mailbox& mailbox, ABuffer& abuffer);

// Renders the samples of the pixels in `rect`: N x N rays per pixel through the centres of the
// strata, each with a footprint of 1/N of a pixel.
void render_tile_distance(const DistanceContext& ctx, const PixelRect& rect, TileAccumulator& acc,
                          RayCounters& counters);

}  // namespace darc
