// The speed-against-error benchmark: renders each scene in-process with the distance hider
// (1x1, 2x2) and the stochastic hider (1x1 .. 16x16), times render_frame, compares every image
// with a cached high-sample stochastic reference, and writes the CSV, the log-log plot and
// docs/performance.md. Run it through scripts/bench-speed-vs-error, which generates the scenes.
//
//   speed_vs_error [options] NAME=FILE.rib...
#include <CLI/CLI.hpp>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "bench/image_error.h"
#include "bench/log_log_plot.h"
#include "bench/reference_cache.h"
#include "bench/speed_error_report.h"
#include "core/scene_builder.h"
#include "integrator/render_frame.h"
#include "parser/rib_parser.h"

namespace darc::bench {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

// The measured settings (N of N x N samples per pixel), cheapest first.
constexpr int kDistanceSamples[] = {1, 2};
constexpr int kStochasticSamples[] = {1, 2, 4, 8, 16};
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
  int max_runs = kDefaultMaxRuns;
  double repeat_budget_seconds = kDefaultRepeatBudgetSeconds;
  int threads = 0;  // 0: all cores
};

double seconds_since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

std::optional<std::string> read_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::nullopt;
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// Parses RIB text and returns its first frame with the acceleration structure built, or
// nullopt (with the diagnostics printed) when it has errors or no frame.
std::optional<Scene> load_scene(const std::string& text, const std::string& name) {
  Diagnostics diag;  // prints to stderr
  std::optional<Scene> scene;
  SceneBuilder::Callbacks cb;
  cb.frame_ready = [&](Scene&& s) {
    if (!scene) scene.emplace(std::move(s));
  };
  SceneBuilder builder(diag, cb);
  RibParser parser(builder, diag);
  parser.parse_string(text, name);
  builder.finish(SourceLoc{});
  if (diag.error_count() > 0 || !scene) return std::nullopt;
  scene->build_acceleration();
  return scene;
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

struct TimedImage {
  Image image;
  double seconds = 0;  // minimum over the runs
  int runs = 0;
};

// Renders `scene` at N x N samples, repeating cheap renders; only render_frame is timed.
TimedImage render_timed(Scene& scene, const RenderOptions& ro, int samples_per_axis, int max_runs,
                        double budget_seconds) {
  scene.output.pixel_samples[0] = scene.output.pixel_samples[1] = samples_per_axis;
  TimedImage best;
  double total = 0;
  while (best.runs < std::max(1, max_runs) && (best.runs == 0 || total < budget_seconds)) {
    Diagnostics diag([](const Diagnostic&) {});  // parse already reported; renders repeat the same
    FrameStats stats;
    Clock::time_point t0 = Clock::now();
    Image image = render_frame(scene, ro, diag, stats);
    double t = seconds_since(t0);
    total += t;
    if (best.runs == 0 || t < best.seconds) best.seconds = t;
    if (best.runs == 0) best.image = std::move(image);  // deterministic: every run gives the same image
    ++best.runs;
  }
  return best;
}

RenderOptions render_options(HiderKind hider, const Options& o) {
  RenderOptions ro;
  ro.hider = hider;
  ro.threads = o.threads;
  ro.seed = kMeasuredSeed;
  return ro;
}

std::optional<Image> reference_image(Scene& scene, const std::string& text, const std::string& name,
                                     const Options& o, double& render_seconds) {
  std::string key = reference_cache_key(text, scene.output.xres, scene.output.yres, o.reference);
  std::string path = reference_cache_path(o.cache_dir, name, key);
  render_seconds = 0;
  if (std::optional<Image> cached = load_cached_reference(path, key, scene.output.xres, scene.output.yres)) {
    std::fprintf(stderr, "  reference: %s (cached)\n", path.c_str());
    return cached;
  }
  std::fprintf(stderr, "  reference: rendering stochastic %dx%d ...\n", o.reference.samples_per_axis,
               o.reference.samples_per_axis);
  RenderOptions ro = render_options(HiderKind::Stochastic, o);
  ro.seed = o.reference.seed;
  TimedImage ref = render_timed(scene, ro, o.reference.samples_per_axis, 1, 0);
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

std::optional<SceneReport> measure_scene(const std::string& name, const std::string& path, const Options& o) {
  std::fprintf(stderr, "%s (%s)\n", name.c_str(), path.c_str());
  std::optional<std::string> text = read_text(path);
  if (!text) {
    std::fprintf(stderr, "speed_vs_error: error: cannot read %s\n", path.c_str());
    return std::nullopt;
  }
  std::optional<Scene> scene = load_scene(*text, path);
  if (!scene) {
    std::fprintf(stderr, "speed_vs_error: error: %s has errors or no frame\n", path.c_str());
    return std::nullopt;
  }
  SceneReport report;
  report.name = name;
  report.xres = scene->output.xres;
  report.yres = scene->output.yres;
  report.curve_segments = scene->curves.size();
  report.widths = strand_width_stats(*scene);
  std::optional<Image> reference = reference_image(*scene, *text, name, o, report.reference_seconds);
  if (!reference) return std::nullopt;

  // One untimed render first: the first render of a process also pays for starting the thread
  // pool and faulting in the scene's pages, which is no property of the setting measured first.
  render_timed(*scene, render_options(HiderKind::Distance, o), 1, 1, 0);

  auto measure = [&](HiderKind hider, int n) {
    TimedImage t = render_timed(*scene, render_options(hider, o), n, o.max_runs, o.repeat_budget_seconds);
    Measurement m{name, to_string(hider), n, t.seconds, t.runs, error_against(t.image, *reference)};
    std::fprintf(stderr, "  %-10s %2dx%-2d %8.3f s (%d runs)  rmse %.4g  max %.4g\n", m.hider.c_str(), n, n,
                 m.seconds, m.runs, m.error.rmse, m.error.max_error);
    report.settings.push_back(m);
  };
  for (int n : kDistanceSamples) measure(HiderKind::Distance, n);
  for (int n : kStochasticSamples) measure(HiderKind::Stochastic, n);

  const std::pair<CoverageModel, const char*> models[] = {
      {CoverageModel::Box, "box"}, {CoverageModel::Disc, "disc"}, {CoverageModel::Square, "square"}};
  for (const auto& [model, label] : models) {
    RenderOptions ro = render_options(HiderKind::Distance, o);
    ro.distance.coverage = model;
    report.coverage.push_back(measure_variant(*scene, ro, o, *reference, label));
  }
  {
    RenderOptions ro = render_options(HiderKind::Distance, o);
    ro.distance.coverage_masks = false;
    report.coverage.push_back(measure_variant(*scene, ro, o, *reference, "scalar"));
  }
  if (measures_sort_interval(o, name)) {
    for (int interval = kMinSortInterval; interval <= kMaxSortInterval; ++interval) {
      RenderOptions ro = render_options(HiderKind::Distance, o);
      ro.distance.sort_interval = interval;
      report.sort_interval.push_back(measure_variant(*scene, ro, o, *reference, std::to_string(interval)));
    }
  }
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
  return run;
}

// One colour per scene (the first colours of matplotlib's "tab10", a familiar set that stays
// distinguishable for common colour-vision deficiencies); the hider is told by the line style.
std::vector<PlotSeries> plot_series(const std::vector<SceneReport>& scenes) {
  static constexpr std::array<std::array<float, 3>, 6> kSceneColors{{{0.12f, 0.47f, 0.71f},
                                                                     {1.00f, 0.50f, 0.05f},
                                                                     {0.17f, 0.63f, 0.17f},
                                                                     {0.84f, 0.15f, 0.16f},
                                                                     {0.58f, 0.40f, 0.74f},
                                                                     {0.55f, 0.34f, 0.29f}}};
  std::vector<PlotSeries> series;
  for (size_t i = 0; i < scenes.size(); ++i) {
    for (const char* hider : {"stochastic", "distance"}) {
      PlotSeries s;
      s.label = scenes[i].name + " " + hider;
      s.color = kSceneColors[i % kSceneColors.size()];
      s.dashed = std::string(hider) == "distance";
      for (const Measurement& m : scenes[i].settings)
        if (m.hider == hider) s.points.push_back({m.seconds, m.error.rmse});
      series.push_back(std::move(s));
    }
  }
  return series;
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
  write_file("speed-vs-error.csv", [&](std::ostream& out) { write_speed_error_csv(out, rows); });
  write_file("performance.md",
             [&](std::ostream& out) { write_performance_markdown(out, describe_run(o), scenes); });

  std::string plot_path = (fs::path(o.out_dir) / "speed-vs-error.png").string();
  PlotText text;
  text.title = "darc: RMSE against render time (" + o.size + " scenes; solid: stochastic, dashed: distance)";
  PlotResult plot = write_log_log_plot(plot_path, plot_series(scenes), text);
  if (!plot.ok) {
    std::fprintf(stderr, "speed_vs_error: error: %s\n", plot.error.c_str());
    return false;
  }
  if (!plot.text_drawn)
    std::fprintf(stderr, "speed_vs_error: warning: OpenImageIO found no font; the plot has no labels "
                         "(install fonts-dejavu-core)\n");
  std::fprintf(stderr, "wrote %s\n", plot_path.c_str());
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
  app.add_option("--out-dir", o.out_dir, "where speed-vs-error.csv, .png and performance.md go");
  app.add_option("--reference-samples", o.reference.samples_per_axis, "N of the N x N reference")->check(
      CLI::Range(1, 256));
  app.add_option("--max-runs", o.max_runs, "most runs of a cheap setting (the minimum time is kept)")
      ->check(CLI::Range(1, 100));
  app.add_option("--repeat-budget", o.repeat_budget_seconds, "repeat a setting while its runs took less (s)");
  app.add_option("--sort-interval-scenes", o.sort_interval_scenes, "comma-separated scenes for the sort-interval sweep (default all)");
  app.add_option("--threads", o.threads, "render threads, 0 = all cores");
  app.add_option("scenes", o.scenes, "NAME=FILE.rib")->required();
  CLI11_PARSE(app, argc, argv);

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
  return write_outputs(o, reports) ? 0 : 1;
}
