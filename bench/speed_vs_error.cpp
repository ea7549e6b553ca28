// The speed-against-error benchmark: renders each scene in-process with the distance hider
// (1x1, 2x2) and the stochastic hider (1x1 .. 16x16), and with --embree the Embree peer
// (1x1 .. 16x16, when built), times the renders, compares every image with a cached high-sample
// stochastic reference, and writes the CSV and docs/performance.md (or, with --report-stem 640,
// docs/performance-640.md with work per ray and memory; with --secondary,
// docs/performance-secondary.md with the contribution-threshold sweeps of the scenes with
// shadows, mirrors and glass). Run it through scripts/bench-speed-vs-error, which generates the
// scenes and draws each CSV's log-log plot with bench/plot_speed_vs_error.py.
//
//   speed_vs_error [options] NAME=FILE.rib...
#include <CLI/CLI.hpp>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "bench/contribution_sweep.h"
#include "bench/image_error.h"
#include "bench/process_memory.h"
#include "bench/reference_cache.h"
#include "bench/scene_loading.h"
#include "bench/speed_error_640.h"
#include "bench/speed_error_report.h"
#include "bench/speed_error_secondary.h"
#include "bench/timed_render.h"
#include "integrator/render_frame.h"
#ifdef DARC_BENCH_HAVE_EMBREE
#include "bench/embree_render.h"
#endif

namespace darc::bench {
namespace {

namespace fs = std::filesystem;

// The measured settings (N of N x N samples per pixel), cheapest first.
constexpr int kDistanceSamples[] = {1, 2};
constexpr int kStochasticSamples[] = {1, 2, 4, 8, 16};  // also the Embree peer's
// The A-buffer sort intervals measured (grid layers between sorts).
constexpr int kMinSortInterval = 1, kMaxSortInterval = 10;
// The seed of every measured render (the reference uses its own, see ReferenceSettings).
constexpr uint32_t kMeasuredSeed = 0;
// Repeats: on a shared, noisy machine the minimum of a few runs is the best estimate of the
// undisturbed time. Cheap settings are repeated up to kDefaultMaxRuns times while the runs so
// far take less than kDefaultRepeatBudgetSeconds; expensive ones run once.
constexpr int kDefaultMaxRuns = 5;
constexpr double kDefaultRepeatBudgetSeconds = 3.0;

struct Options {
  std::string size = "large";
  std::string cache_dir = "build/bench-cache";
  std::string out_dir = "docs";
  std::vector<std::string> scenes;                // NAME=FILE.rib
  std::string sort_interval_scenes;  // comma-separated names; empty: all
  ReferenceSettings reference;
  std::vector<std::string> reference_overrides;  // NAME=N: that scene's reference is N x N
  std::vector<std::string> frame_overrides;      // NAME=N: that scene is its file's frame N (default 1)
  int max_runs = kDefaultMaxRuns;
  double repeat_budget_seconds = kDefaultRepeatBudgetSeconds;
  int threads = 0;  // 0: all cores
  int stochastic_max = 16;    // costliest stochastic (and Embree) N x N measured
  bool variants = true;       // the coverage-model and sort-interval sweeps of the distance hider
  bool embree = false;        // measure the Embree peer (when built)
  std::string report_stem;    // "640": performance-640.md etc. with the 640 report's tables
  bool quick = false;         // label the report as the quick smoke run
  bool references_only = false;  // fill the reference cache, measure and write nothing
  std::string accelerator = to_string(kDefaultAccelerator);  // "bvh" or "grid"
  // The secondary-ray report: references at threshold 0, the contribution-threshold sweeps,
  // performance-secondary.md.
  bool secondary = false;
  float contribution_threshold = kDefaultContributionThreshold;  // of the measured renders
  int sweep_stochastic = 2;   // N of the stochastic N x N sweep beside the distance 1x1 one; 0: none
};

AcceleratorKind accelerator_kind(const Options& o) {
  return o.accelerator == "grid" ? AcceleratorKind::Grid : AcceleratorKind::Bvh;
}

int render_threads(const Options& o) {
  return o.threads > 0 ? o.threads : std::max(1, int(std::thread::hardware_concurrency()));
}

// Width in pixels of every visible segment end: the world width over the world size of a pixel
// at that point (from the rays through neighbouring raster positions).
WidthStats strand_width_stats(const Scene& scene) {
  const Camera& cam = scene.camera;
  const CurveSet& cs = scene.curves;
  std::vector<double> px;
  for (size_t i = 0; i < cs.size(); ++i) {
    for (size_t end : {size_t(0), kControlPointsPerSegment - 1}) {
      Vec3f p = cs.control_points(i)[end];
      double rx, ry;
      if (!cam.world_to_raster(Vec3d{p.x, p.y, p.z}, rx, ry)) continue;
      if (rx < 0 || ry < 0 || rx >= scene.output.xres || ry >= scene.output.yres) continue;
      Ray r0 = cam.generate_ray(rx, ry), r1 = cam.generate_ray(rx + 1, ry);
      float t = length(p - r0.o);
      float pixel = length((r1.o + r1.d * t) - (r0.o + r0.d * t));
      float w = cs.widths(i)[end];
      if (pixel > 0 && w > 0) px.push_back(double(w) / double(pixel));
    }
  }
  WidthStats s;
  s.count = px.size();
  if (px.empty()) return s;
  std::sort(px.begin(), px.end());
  auto quantile = [&](double q) { return px[std::min(px.size() - 1, size_t(q * double(px.size() - 1) + 0.5))]; };
  s.min = px.front(), s.p5 = quantile(0.05), s.median = quantile(0.5), s.p95 = quantile(0.95), s.max = px.back();
  return s;
}

WorkCounters work_of(const RayCounters& c) {
  WorkCounters w;
  w.primary_rays = c.primary_rays;
  w.segment_tests = c.segment_tests;
  w.fragments = c.fragments;
  w.cells_visited = c.cells_visited;
  w.secondary_rays = c.secondary_rays;
  w.pruned_rays = c.pruned_rays;
  w.surface_tests = c.surface_tests;
  w.surface_pieces = c.surface_pieces;
  w.shadow_rays = c.traced_by_kind[int(SecondaryKind::Shadow)];
  w.shadow_segment_tests = c.shadow_segment_tests;
  return w;
}

RenderOptions render_options(HiderKind hider, const Options& o) {
  RenderOptions ro;
  ro.hider = hider;
  ro.threads = o.threads;
  ro.seed = kMeasuredSeed;
  ro.contribution_threshold = o.contribution_threshold;
  return ro;
}

// N of the NAME=N among `overrides` for scene `name`, or `fallback`.
int override_for(const std::vector<std::string>& overrides, const std::string& name, int fallback) {
  for (const std::string& arg : overrides) {
    size_t eq = arg.find('=');
    if (eq != std::string::npos && arg.substr(0, eq) == name) return std::max(1, std::atoi(arg.c_str() + eq + 1));
  }
  return fallback;
}

// The scene's reference settings: the run's, or NAME=N from --reference-samples-for.
ReferenceSettings reference_for(const Options& o, const std::string& name) {
  ReferenceSettings r = o.reference;
  r.samples_per_axis = override_for(o.reference_overrides, name, r.samples_per_axis);
  return r;
}

std::optional<Image> reference_image(Scene& scene, const std::string& text, const std::string& name,
                                     const Options& o, const ReferenceSettings& settings, double& render_seconds) {
  std::string key = reference_cache_key(text, scene.output.xres, scene.output.yres, settings);
  std::string path = reference_cache_path(o.cache_dir, name, key);
  render_seconds = 0;
  if (std::optional<Image> cached = load_cached_reference(path, key, scene.output.xres, scene.output.yres)) {
    std::fprintf(stderr, "  reference: %s (cached)\n", path.c_str());
    return cached;
  }
  std::fprintf(stderr, "  reference: rendering stochastic %dx%d ...\n", settings.samples_per_axis,
               settings.samples_per_axis);
  RenderOptions ro = render_options(HiderKind::Stochastic, o);
  ro.seed = settings.seed;
  ro.contribution_threshold = settings.contribution_threshold;
  TimedImage ref = render_timed(scene, ro, settings.samples_per_axis, 1, 0);
  render_seconds = ref.seconds;
  std::string error = store_cached_reference(path, ref.image, key);
  if (!error.empty()) std::fprintf(stderr, "speed_vs_error: warning: reference not cached: %s\n", error.c_str());
  std::fprintf(stderr, "  reference: %.3g s, %s\n", ref.seconds, path.c_str());
  return std::move(ref.image);
}

ImageError error_against(const Image& image, const Image& reference) {
  std::optional<ImageError> e = compare_rgba(image, reference);
  return e ? *e : ImageError{1.0, 1.0, 0};  // cannot happen for images of the same scene; never NaN
}

VariantMeasurement measure_variant(Scene& scene, const RenderOptions& ro, const Options& o, const Image& reference,
                                   std::string label) {
  TimedImage t = render_timed(scene, ro, 1, o.max_runs, o.repeat_budget_seconds);
  VariantMeasurement v{std::move(label), t.seconds, t.runs, error_against(t.image, reference)};
  std::fprintf(stderr, "  distance 1x1 %-8s %8.3f s  rmse %.4g\n", v.label.c_str(), v.seconds, v.error.rmse);
  return v;
}

bool measures_sort_interval(const Options& o, const std::string& name) {
  if (o.sort_interval_scenes.empty()) return true;
  std::istringstream names(o.sort_interval_scenes);
  for (std::string n; std::getline(names, n, ',');)
    if (n == name) return true;
  return false;
}

// The Embree peer's settings, 1x1 .. stochastic_max, appended to the report (when built).
// `stochastic` holds darc's stochastic image per N of the same run, for the agreement check.
void measure_embree(const Scene& scene, const Options& o, const Image& reference,
                    const std::map<int, Image>& stochastic, SceneReport& report) {
#ifdef DARC_BENCH_HAVE_EMBREE
  uint64_t resident_before = resident_bytes();
  EmbreeBuildStats build;
  std::string error;
  std::unique_ptr<EmbreeScene> embree = EmbreeScene::build(scene, o.threads, build, error);
  if (!embree) {
    std::fprintf(stderr, "speed_vs_error: warning: no Embree rows: %s\n", error.c_str());
    return;
  }
  report.load.embree_build_seconds = build.seconds;
  report.load.embree_bytes = build.embree_bytes;
  report.load.embree_resident_growth_bytes = resident_bytes() - std::min(resident_bytes(), resident_before);
  std::fprintf(stderr, "  embree     BVH %.3f s, %.1f MB\n", build.seconds, double(build.embree_bytes) / 1e6);
  auto render = [&](int n) {
    Diagnostics diag([](const Diagnostic&) {});
    EmbreeRenderStats stats;
    Image image = render_embree(*embree, {n, o.threads, kMeasuredSeed}, diag, stats);
    return std::make_pair(std::move(image), stats);
  };
  render(1);  // untimed, as the first darc render: thread pool start-up and page faults
  for (int n : kStochasticSamples) {
    if (n > o.stochastic_max) break;
    TimedImage best;
    WorkCounters work;
    double total = 0;
    while (best.runs < std::max(1, o.max_runs) && (best.runs == 0 || total < o.repeat_budget_seconds)) {
      auto [image, stats] = render(n);
      total += stats.render_seconds;
      if (best.runs == 0 || stats.render_seconds < best.seconds) best.seconds = stats.render_seconds;
      if (best.runs == 0) {
        best.image = std::move(image);
        work.primary_rays = stats.primary_rays;
        work.intersect_calls = stats.intersect_calls;
      }
      ++best.runs;
    }
    Measurement m{report.name, "embree", n, best.seconds, best.runs, error_against(best.image, reference)};
    std::fprintf(stderr, "  %-10s %2dx%-2d %8.3f s (%d runs)  rmse %.4g  max %.4g\n", m.hider.c_str(), n, n,
                 m.seconds, m.runs, m.error.rmse, m.error.max_error);
    report.settings.push_back(m);
    report.work.push_back(work);
    if (auto it = stochastic.find(n); it != stochastic.end()) {
      ImageError agreement = error_against(best.image, it->second);
      report.embree_vs_stochastic.push_back({n, agreement});
      std::fprintf(stderr, "  embree %dx%d vs darc stochastic %dx%d (same rays): rmse %.3g  max %.3g\n", n, n, n, n,
                   agreement.rmse, agreement.max_error);
    }
  }
#else
  (void)scene, (void)o, (void)reference, (void)stochastic, (void)report;
#endif
}

// The contribution-threshold sweeps of the secondary-ray report: the distance hider at 1x1 and
// the stochastic hider at sweep_stochastic x sweep_stochastic, at every swept threshold.
void measure_contribution_sweeps(Scene& scene, const Options& o, const Image& reference, SceneReport& report) {
  SweepSettings settings{o.max_runs, o.repeat_budget_seconds, {}};
  std::vector<std::pair<HiderKind, int>> sweeps{{HiderKind::Distance, 1}};
  if (o.sweep_stochastic > 0) sweeps.push_back({HiderKind::Stochastic, o.sweep_stochastic});
  for (const auto& [hider, n] : sweeps) {
    settings.on_measured = [&, n = n, hider = hider](const ThresholdMeasurement& m) {
      std::fprintf(stderr,
                   "  %-10s %2dx%-2d threshold %-6g %8.3f s (%d runs)  traced %llu/%llu/%llu  pruned %llu/%llu/%llu  "
                   "rmse vs 0 %.3g  vs reference %.3g\n",
                   to_string(hider).c_str(), n, n, double(m.threshold), m.seconds, m.runs,
                   (unsigned long long)m.traced[0], (unsigned long long)m.traced[1], (unsigned long long)m.traced[2],
                   (unsigned long long)m.pruned[0], (unsigned long long)m.pruned[1], (unsigned long long)m.pruned[2],
                   m.vs_unpruned.rmse, m.vs_reference.rmse);
    };
    report.contribution_sweeps.push_back(measure_contribution_sweep(
        scene, render_options(hider, o), n, kSweptContributionThresholds, reference, settings));
  }
}

void measure_variants(Scene& scene, const Options& o, const Image& reference, SceneReport& report) {
  const std::pair<CoverageModel, const char*> models[] = {
      {CoverageModel::Box, "box"}, {CoverageModel::Disc, "disc"}, {CoverageModel::Square, "square"}};
  for (const auto& [model, label] : models) {
    RenderOptions ro = render_options(HiderKind::Distance, o);
    ro.distance.coverage = model;
    report.coverage.push_back(measure_variant(scene, ro, o, reference, label));
  }
  {
    RenderOptions ro = render_options(HiderKind::Distance, o);
    ro.distance.coverage_masks = false;
    report.coverage.push_back(measure_variant(scene, ro, o, reference, "scalar"));
  }
  if (measures_sort_interval(o, report.name)) {
    for (int interval = kMinSortInterval; interval <= kMaxSortInterval; ++interval) {
      RenderOptions ro = render_options(HiderKind::Distance, o);
      ro.distance.sort_interval = interval;
      report.sort_interval.push_back(measure_variant(scene, ro, o, reference, std::to_string(interval)));
    }
  }
}

std::optional<SceneReport> measure_scene(const std::string& name, const std::string& path, const Options& o) {
  std::fprintf(stderr, "%s (%s)\n", name.c_str(), path.c_str());
  std::optional<std::string> text = read_text(path);
  if (!text) {
    std::fprintf(stderr, "speed_vs_error: error: cannot read %s\n", path.c_str());
    return std::nullopt;
  }
  const bool peak_reset = reset_peak_resident();
  const int frame = override_for(o.frame_overrides, name, 1);
  std::optional<LoadedScene> loaded = load_scene(*text, path, true, accelerator_kind(o), frame);
  if (!loaded) {
    std::fprintf(stderr, "speed_vs_error: error: %s has errors or no frame %d\n", path.c_str(), frame);
    return std::nullopt;
  }
  Scene& scene = loaded->scene;
  SceneReport report;
  report.name = name;
  report.xres = scene.output.xres;
  report.yres = scene.output.yres;
  report.curve_segments = scene.curves.size();
  report.widths = strand_width_stats(scene);
  report.load.rib_bytes = text->size();
  report.load.parse_seconds = loaded->parse_seconds;
  report.load.build_seconds = loaded->build_seconds;
  report.load.accelerator_bytes = scene.accel.memory_bytes();
  report.load.curve_bytes = scene.curves.memory_bytes();
  report.load.resident_growth_bytes =
      loaded->resident_after_bytes - std::min(loaded->resident_after_bytes, loaded->resident_before_bytes);
  report.load.heap_growth_bytes =
      loaded->heap_after_bytes - std::min(loaded->heap_after_bytes, loaded->heap_before_bytes);
  std::fprintf(stderr, "  load: parse %.3f s, acceleration %.3f s, heap +%.1f MB, resident +%.1f MB\n", loaded->parse_seconds,
               loaded->build_seconds, double(report.load.heap_growth_bytes) / 1e6,
               double(report.load.resident_growth_bytes) / 1e6);
  // The reference cache is keyed by the text: a frame other than the first is another scene.
  if (frame != 1) *text += "\n# frame " + std::to_string(frame);
  const ReferenceSettings reference_settings = reference_for(o, name);
  report.reference_samples_per_axis = reference_settings.samples_per_axis;
  std::optional<Image> reference = reference_image(scene, *text, name, o, reference_settings, report.reference_seconds);
  if (!reference) return std::nullopt;
  if (o.references_only) return report;

  // One untimed render first: the first render of a process also pays for starting the thread
  // pool and faulting in the scene's pages, which is no property of the setting measured first.
  render_timed(scene, render_options(HiderKind::Distance, o), 1, 1, 0);

  std::map<int, Image> stochastic_images;  // by N, for the Embree peer's agreement check
  auto measure = [&](HiderKind hider, int n) {
    TimedImage t = render_timed(scene, render_options(hider, o), n, o.max_runs, o.repeat_budget_seconds);
    Measurement m{name, to_string(hider), n, t.seconds, t.runs, error_against(t.image, *reference)};
    if (hider == HiderKind::Stochastic && o.embree) stochastic_images[n] = t.image;
    std::fprintf(stderr, "  %-10s %2dx%-2d %8.3f s (%d runs)  rmse %.4g  max %.4g\n", m.hider.c_str(), n, n,
                 m.seconds, m.runs, m.error.rmse, m.error.max_error);
    report.settings.push_back(m);
    report.work.push_back(work_of(t.counters));
  };
  for (int n : kDistanceSamples) measure(HiderKind::Distance, n);
  for (int n : kStochasticSamples)
    if (n <= o.stochastic_max) measure(HiderKind::Stochastic, n);
  if (o.embree) measure_embree(scene, o, *reference, stochastic_images, report);
  if (o.variants) measure_variants(scene, o, *reference, report);
  if (o.secondary) measure_contribution_sweeps(scene, o, *reference, report);
  report.load.peak_resident_bytes = peak_resident_bytes();
  report.load.peak_is_per_scene = peak_reset;
  return report;
}

RunDescription describe_run(const Options& o) {
  RunDescription run;
  run.size = o.size;
  std::time_t now = std::time(nullptr);
  std::tm utc{};
  gmtime_r(&now, &utc);
  char date[32];
  std::strftime(date, sizeof date, "%Y-%m-%d %H:%M UTC", &utc);
  run.date = date;
  run.cores = int(std::thread::hardware_concurrency());
  std::ifstream cpuinfo("/proc/cpuinfo");
  for (std::string line; std::getline(cpuinfo, line);) {
    if (line.rfind("model name", 0) == 0 && line.find(':') != std::string::npos) {
      run.cpu_model = line.substr(line.find(':') + 2);
      break;
    }
  }
  run.reference_samples_per_axis = o.reference.samples_per_axis;
  run.reference_seed = o.reference.seed;
  run.max_runs = o.max_runs;
  run.repeat_budget_seconds = o.repeat_budget_seconds;
  run.threads = render_threads(o);
#ifdef DARC_BENCH_HAVE_EMBREE
  if (o.embree) run.embree = "Embree " + std::to_string(RTC_VERSION_MAJOR) + "." + std::to_string(RTC_VERSION_MINOR) +
                             "." + std::to_string(RTC_VERSION_PATCH);
#endif
  run.quick = o.quick;
  run.accelerator = o.accelerator;
  run.contribution_threshold = o.contribution_threshold;
  run.reference_contribution_threshold = o.reference.contribution_threshold;
  return run;
}

bool write_outputs(const Options& o, const std::vector<SceneReport>& scenes) {
  std::error_code ec;
  fs::create_directories(o.out_dir, ec);
  bool ok = true;
  std::vector<Measurement> rows;
  for (const SceneReport& s : scenes) rows.insert(rows.end(), s.settings.begin(), s.settings.end());
  auto write_file = [&](const std::string& file, auto writer) {
    fs::path target = fs::path(o.out_dir) / file, temp = target;
    temp += ".tmp";
    {
      std::ofstream out(temp);
      writer(out);
      if (!out) {
        std::fprintf(stderr, "speed_vs_error: error: cannot write %s\n", temp.c_str());
        ok = false;
        return;
      }
    }
    fs::rename(temp, target, ec);
    if (ec) ok = false;
    std::fprintf(stderr, "wrote %s\n", target.c_str());
  };
  const std::string suffix = o.report_stem.empty() ? "" : "-" + o.report_stem;
  if (o.secondary) {
    write_file("speed-vs-error" + suffix + ".csv", [&](std::ostream& out) {
      write_speed_error_640_csv(out, scenes, render_threads(o), o.reference.samples_per_axis);
    });
    write_file("speed-vs-error" + suffix + "-pruning.csv",
               [&](std::ostream& out) { write_contribution_sweep_csv(out, scenes); });
    write_file("performance" + suffix + ".md",
               [&](std::ostream& out) { write_performance_secondary_markdown(out, describe_run(o), scenes); });
  } else if (o.report_stem.empty()) {
    write_file("speed-vs-error.csv", [&](std::ostream& out) { write_speed_error_csv(out, rows); });
    write_file("performance.md",
               [&](std::ostream& out) { write_performance_markdown(out, describe_run(o), scenes); });
  } else {
    write_file("speed-vs-error" + suffix + ".csv", [&](std::ostream& out) {
      write_speed_error_640_csv(out, scenes, render_threads(o), o.reference.samples_per_axis);
    });
    write_file("performance" + suffix + ".md",
               [&](std::ostream& out) { write_performance_640_markdown(out, describe_run(o), scenes); });
  }

  return ok;
}

}  // namespace
}  // namespace darc::bench

int main(int argc, char** argv) {
  using namespace darc::bench;
  Options o;
  CLI::App app{"speed against error: both hiders against a stochastic reference"};
  app.add_option("--size", o.size, "label of the scene size (small|large), for the report");
  app.add_option("--cache", o.cache_dir, "directory of cached reference images");
  app.add_option("--out-dir", o.out_dir, "where speed-vs-error.csv and performance.md go");
  app.add_option("--reference-samples", o.reference.samples_per_axis, "N of the N x N reference")->check(
      CLI::Range(1, 256));
  app.add_option("--max-runs", o.max_runs, "most runs of a cheap setting (the minimum time is kept)")
      ->check(CLI::Range(1, 100));
  app.add_option("--repeat-budget", o.repeat_budget_seconds, "repeat a setting while its runs took less (s)");
  app.add_option("--sort-interval-scenes", o.sort_interval_scenes, "comma-separated scenes for the sort-interval sweep (default all)");
  app.add_option("--threads", o.threads, "render threads, 0 = all cores");
  app.add_option("--reference-samples-for", o.reference_overrides, "NAME=N: scene NAME's reference is N x N");
  app.add_option("--frame-for", o.frame_overrides, "NAME=N: scene NAME is frame N of its file (default 1)");
  app.add_option("--stochastic-max", o.stochastic_max, "costliest stochastic and Embree N x N measured")
      ->check(CLI::IsMember({1, 2, 4, 8, 16}));
  app.add_flag("!--no-variants", o.variants, "skip the coverage-model and sort-interval sweeps");
  app.add_flag("--embree", o.embree, "also measure the Embree peer (needs a build with Embree)");
  app.add_option("--report-stem", o.report_stem,
                 "write performance-STEM.md, speed-vs-error-STEM.csv with work per ray and memory");
  app.add_flag("--quick", o.quick, "label the report as the quick smoke run");
  app.add_flag("--references-only", o.references_only,
               "render (or find cached) the references and stop: no timing, no report (a first, untimed "
               "pass, e.g. at low priority while the machine is busy)");
  app.add_option("--accelerator", o.accelerator, "darc's acceleration structure (default: the renderer's)")
      ->check(CLI::IsMember({"bvh", "grid"}));
  app.add_flag("--secondary", o.secondary,
               "the secondary-ray report: references with every secondary ray traced, the contribution-threshold "
               "sweeps, performance-secondary.md, speed-vs-error-secondary(-pruning).csv");
  app.add_option("--contribution-threshold", o.contribution_threshold,
                 "contribution threshold of the measured renders (default: the renderer's)")
      ->check(CLI::Range(0.0f, 1.0f));
  app.add_option("--sweep-stochastic", o.sweep_stochastic,
                 "--secondary: N of the stochastic N x N threshold sweep (0: only the distance hider's)")
      ->check(CLI::Range(0, 16));
  app.add_option("scenes", o.scenes, "NAME=FILE.rib")->required();
  CLI11_PARSE(app, argc, argv);
#ifndef DARC_BENCH_HAVE_EMBREE
  if (o.embree) {
    std::fprintf(stderr, "speed_vs_error: warning: built without Embree (scripts/setup --bench): no Embree rows\n");
    o.embree = false;
  }
#endif

  if (o.secondary) {
    o.report_stem = "secondary";
    o.reference.contribution_threshold = 0;  // the reference traces every secondary ray
    if (o.embree) {
      std::fprintf(stderr,
                   "speed_vs_error: warning: --secondary: the Embree peer traces camera rays only: no Embree rows\n");
      o.embree = false;
    }
  }

  std::vector<SceneReport> reports;
  for (const std::string& arg : o.scenes) {
    size_t eq = arg.find('=');
    if (eq == std::string::npos || eq == 0) {
      std::fprintf(stderr, "speed_vs_error: expected NAME=FILE.rib, got \"%s\"\n", arg.c_str());
      return 2;
    }
    std::optional<SceneReport> r = measure_scene(arg.substr(0, eq), arg.substr(eq + 1), o);
    if (!r) return 1;
    reports.push_back(std::move(*r));
  }
  if (o.references_only) return 0;
  return write_outputs(o, reports) ? 0 : 1;
}
