// The Embree peer on its own: loads a RIB with darc's SceneBuilder, builds an Embree 3 scene of
// the same geometry (bench/embree_scene.h) and renders it with N x N jittered samples and darc's
// shading (bench/embree_render.h). Prints the build and render times separately; with
// --compare-darc it also renders darc's stochastic hider with the same samples and seed and
// prints the error between the two images (they trace the same rays through the same flat
// ribbons, so it must be far below the noise of either).
//
// --max-rmse X makes that comparison a check: exit 1 when the RMSE is above X (ctest runs it
// on curves, quadrics and tessellated surfaces when Embree is installed).
//
//   embree_peer [--samples N] [--threads T] [--seed S] [-o OUT.exr|.png] [--compare-darc [--max-rmse X]] FILE.rib
#include <CLI/CLI.hpp>

#include <chrono>
#include <cstdio>
#include <string>

#include "bench/embree_render.h"
#include "bench/image_error.h"
#include "bench/process_memory.h"
#include "bench/scene_loading.h"
#include "integrator/color_config.h"
#include "integrator/image_writer.h"
#include "integrator/render_frame.h"

int main(int argc, char** argv) {
  using namespace darc;
  using namespace darc::bench;
  std::string rib, output;
  EmbreeRenderOptions options;
  bool compare_darc = false;
  double max_rmse = -1;
  CLI::App app{"Embree 3 peer: the stochastic method with Embree's BVH and curve intersectors, darc's shading"};
  app.add_option("--samples", options.samples_per_axis, "N of the N x N jittered samples per pixel")
      ->check(CLI::Range(1, 256));
  app.add_option("--threads", options.threads, "render and build threads, 0 = all cores");
  app.add_option("--seed", options.seed, "seed of the sample positions (darc's --seed)");
  app.add_option("-o,--output", output, "write the image (.exr scene-linear, .png/.tif through the display transform)");
  app.add_flag("--compare-darc", compare_darc, "also render darc's stochastic hider and print the RMSE between them");
  app.add_option("--max-rmse", max_rmse, "with --compare-darc: exit 1 when the RMSE is above this")
      ->needs("--compare-darc");
  app.add_option("rib", rib, "FILE.rib")->required();
  CLI11_PARSE(app, argc, argv);

  std::optional<std::string> text = read_text(rib);
  if (!text) {
    std::fprintf(stderr, "embree_peer: error: cannot read %s\n", rib.c_str());
    return 1;
  }
  std::optional<LoadedScene> loaded = load_scene(*text, rib, compare_darc);
  if (!loaded) {
    std::fprintf(stderr, "embree_peer: error: %s has errors or no frame\n", rib.c_str());
    return 3;
  }
  const Scene& scene = loaded->scene;
  std::printf("scene %s: %dx%d, %zu curve segments, %zu surfaces; parse %.3f s\n", rib.c_str(), scene.output.xres,
              scene.output.yres, scene.curves.size(), scene.surfaces.size(), loaded->parse_seconds);

  uint64_t rss_before = resident_bytes();
  EmbreeBuildStats build;
  std::string error;
  std::unique_ptr<EmbreeScene> embree = EmbreeScene::build(scene, options.threads, build, error);
  if (!embree) {
    std::fprintf(stderr, "embree_peer: error: %s\n", error.c_str());
    return 1;
  }
  uint64_t rss_after = resident_bytes();
  const double segments = std::max<double>(1, double(build.curve_segments));
  std::printf("embree build: %.3f s BVH (%.3f us/segment) + %.3f s buffers; %llu segments, %llu triangles, %llu user "
              "primitives; Embree memory %.1f MB (%.0f B/segment), resident +%.1f MB\n",
              build.seconds, 1e6 * build.seconds / segments, build.setup_seconds,
              (unsigned long long)build.curve_segments, (unsigned long long)build.triangles,
              (unsigned long long)build.user_primitives, double(build.embree_bytes) / 1e6,
              double(build.embree_bytes) / segments, double(rss_after - rss_before) / 1e6);

  Diagnostics diag;
  EmbreeRenderStats stats;
  Image image = render_embree(*embree, options, diag, stats);
  std::printf("embree render %dx%d: %.3f s, %llu primary rays, %.3f rtcIntersect1 per primary ray\n",
              options.samples_per_axis, options.samples_per_axis, stats.render_seconds,
              (unsigned long long)stats.primary_rays,
              double(stats.intersect_calls) / std::max<double>(1, double(stats.primary_rays)));

  if (!output.empty()) {
    ImageMetadata metadata;
    metadata.software = "darc embree_peer";
    metadata.hider = "embree";
    metadata.samples_per_pixel = options.samples_per_axis * options.samples_per_axis;
    metadata.render_seconds = float(stats.render_seconds);
    WriteResult w = write_image(output, image, metadata, ColorConfig::builtin(), "rgba");
    if (!w.ok) {
      std::fprintf(stderr, "embree_peer: error: %s\n", w.error.c_str());
      return 1;
    }
    std::printf("wrote %s\n", output.c_str());
  }

  if (compare_darc) {
    Scene darc_scene = scene;  // the pixel samples are set per render
    darc_scene.output.pixel_samples[0] = darc_scene.output.pixel_samples[1] = options.samples_per_axis;
    RenderOptions ro;
    ro.hider = HiderKind::Stochastic;
    ro.threads = options.threads;
    ro.seed = options.seed;
    FrameStats fs;
    Image darc_image = render_frame(darc_scene, ro, diag, fs);
    std::optional<ImageError> e = compare_rgba(image, darc_image);
    if (!e) {
      std::fprintf(stderr, "embree_peer: error: the images cannot be compared\n");
      return 1;
    }
    std::printf("darc stochastic %dx%d: %.3f s; embree vs darc: RMSE %.3g, max %.3g (RGBA)\n",
                options.samples_per_axis, options.samples_per_axis, fs.render_seconds, e->rmse, e->max_error);
    if (max_rmse >= 0 && !(e->rmse <= max_rmse)) {
      std::fprintf(stderr, "embree_peer: error: RMSE %.3g against darc is above --max-rmse %.3g\n", e->rmse, max_rmse);
      return 1;
    }
  }
  return 0;
}
