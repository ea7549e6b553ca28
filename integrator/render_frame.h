// Renders one Scene into an Image with the chosen hider: tiles in parallel (oneTBB), each into
// its own accumulator, merged in tile order so the result is bitwise identical for any
// thread count.
#pragma once

#include "core/scene/scene.h"
#include "core/footprint/coverage.h"
#include "integrator/contribution.h"
#include "integrator/distance_hider.h"
#include "integrator/film.h"
#include "integrator/render_stats.h"
#include "parser/diagnostics.h"

#include <cstdint>
#include <functional>
#include <string>

namespace darc {

enum class HiderKind { Distance, Stochastic };

std::string to_string(HiderKind h);

struct RenderOptions {
  HiderKind hider = HiderKind::Stochastic;
  int threads = 0;     // 0: all cores
  uint32_t seed = 0;
  DistanceHiderSettings distance;  // --hider distance only
  // Secondary rays whose contribution weight (how much they can still change the pixel) is below
  // this are not traced (--contribution-threshold; 0 traces every ray).
  float contribution_threshold = kDefaultContributionThreshold;
  // Called with the fraction of tiles done, from one thread at a time.
  std::function<void(double)> progress;
};

// The pixel rectangle a CropWindow selects (RI Spec 3.2 §4.1.1: ceil(xres*xmin) to
// ceil(xres*xmax - 1) inclusive).
PixelRect crop_pixels(const OutputSettings& out);

Image render_frame(const Scene& scene, const RenderOptions& options, Diagnostics& diag, FrameStats& stats);

}  // namespace darc
