#include "integrator/render_frame.h"

#include "integrator/distance_hider.h"
#include "integrator/stochastic_hider.h"
#include "integrator/tracer.h"
#include "shading/scene_shading.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <mutex>

namespace darc {

std::string to_string(HiderKind h) { return h == HiderKind::Distance ? "distance" : "stochastic"; }

PixelRect crop_pixels(const OutputSettings& out) {
  int x0 = int(std::ceil(out.xres * out.crop[0]));
  int x1 = int(std::ceil(out.xres * out.crop[1] - 1)) + 1;
  int y0 = int(std::ceil(out.yres * out.crop[2]));
  int y1 = int(std::ceil(out.yres * out.crop[3] - 1)) + 1;
  x0 = std::clamp(x0, 0, out.xres);
  x1 = std::clamp(x1, x0, out.xres);
  y0 = std::clamp(y0, 0, out.yres);
  y1 = std::clamp(y1, y0, out.yres);
  return {x0, y0, x1, y1};
}

Image render_frame(const Scene& scene, const RenderOptions& options, Diagnostics& diag, FrameStats& stats) {
  auto start = std::chrono::steady_clock::now();
  const OutputSettings& out = scene.output;
  std::optional<PixelFilter> filter =
      make_pixel_filter(out.filter_name, float(out.filter_width[0]), float(out.filter_width[1]));
  if (!filter) filter = make_pixel_filter("gaussian", 2, 2);
  Film film(out.xres, out.yres, crop_pixels(out), *filter);

  SceneShading shading(scene, diag);
  Tracer tracer(scene);
  HiderContext ctx{scene,
                   shading,
                   tracer,
                   options.seed,
                   std::max(1, int(std::lround(out.pixel_samples[0]))),
                   std::max(1, int(std::lround(out.pixel_samples[1]))),
                   make_secondary_settings(scene, options.contribution_threshold)};

  std::optional<DistanceContext> distance;
  if (options.hider == HiderKind::Distance) distance.emplace(make_distance_context(ctx, options.distance));

  std::vector<PixelRect> tiles = film.tiles();
  std::vector<std::optional<TileAccumulator>> accumulators(tiles.size());
  std::vector<RayCounters> counters(tiles.size());
  size_t done = 0;
  std::mutex progress_mutex;

  int threads = options.threads > 0 ? options.threads : tbb::this_task_arena::max_concurrency();
  tbb::task_arena arena(threads);
  arena.execute([&] {
    tbb::parallel_for(tbb::blocked_range<size_t>(0, tiles.size(), 1), [&](const tbb::blocked_range<size_t>& r) {
      for (size_t i = r.begin(); i != r.end(); ++i) {
        accumulators[i].emplace(film.make_accumulator(tiles[i]));
        if (distance)
          render_tile_distance(*distance, tiles[i], *accumulators[i], counters[i]);
        else
          render_tile_stochastic(ctx, tiles[i], *accumulators[i], counters[i]);
        if (options.progress) {
          // Counted under the lock so that reports arrive in increasing order.
          std::lock_guard lock(progress_mutex);
          options.progress(double(++done) / double(tiles.size()));
        }
      }
    });
  });
  // Merge in tile order: the same float sums for any thread count.
  for (size_t i = 0; i < tiles.size(); ++i) {
    film.merge(*accumulators[i]);
    stats.counters += counters[i];
  }
  Image image = film.resolve(float(out.exposure_gain), float(out.exposure_gamma));
  stats.render_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return image;
}

}  // namespace darc
