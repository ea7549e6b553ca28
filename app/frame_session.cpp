#include "app/frame_session.h"

#include "app/disk_reserve.h"
#include "app/frame_list.h"
#include "app/process_memory.h"
#include "app/stats_file.h"
#include "integrator/image_writer.h"
#include "integrator/render_frame.h"

#include <cctype>
#include <cstdio>
#include <filesystem>
#include <optional>

namespace darc {

namespace {

namespace fs = std::filesystem;
// --skip-existing: a frame counts as done when its file exists, its header opens and it records
// no errors (a frame rendered without some of its requests is rendered again).
enum class ExistingFrame { Missing, Done, HasErrors };

ExistingFrame existing_frame(const std::string& path) {
  if (!fs::exists(path)) return ExistingFrame::Missing;
  const std::optional<std::int64_t> errors = read_recorded_error_count(path);
  if (!errors) return ExistingFrame::Missing;  // unreadable: render it again
  return *errors > 0 ? ExistingFrame::HasErrors : ExistingFrame::Done;
}

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

bool has_image_extension(const std::string& name) {
  std::string ext = fs::path(name).extension().string();
  for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
  return ext == ".exr" || ext == ".tif" || ext == ".tiff" || ext == ".png" || ext == ".jpg" || ext == ".jpeg";
}

// The file a frame goes to: -o or the Display name, with the frame number substituted, and an
// extension chosen from the display type when the name has none we can write.
std::string output_path(const AppOptions& o, const OutputSettings& out) {
  std::string name = o.output.empty() ? out.display_name : o.output;
  name = substitute_frame_number(name, out.frame_number);
  if (!has_image_extension(name))
    name += (out.display_type == "openexr" || out.display_type == "exr") ? ".exr" : ".tif";
  return name;
}

// Per kind of secondary ray (shadow, reflection, refraction): traced and pruned.
nlohmann::json by_kind(const RayCounters& c) {
  nlohmann::json j = nlohmann::json::object();
  for (int k = 0; k < kSecondaryKinds; ++k)
    j[to_string(SecondaryKind(k))] = {{"traced", c.traced_by_kind[k]}, {"pruned", c.pruned_by_kind[k]}};
  return j;
}

nlohmann::json counters_json(const RayCounters& c) {
  return {{"primary_rays", c.primary_rays},
          {"secondary_rays", c.secondary_rays},
          {"curve_segment_tests", c.segment_tests},
          {"surface_tests", c.surface_tests},
          {"surface_pieces", c.surface_pieces},
          {"shadow_segment_tests", c.shadow_segment_tests},
          {"shadow_surface_pieces", c.shadow_surface_pieces},
          {"fragment_merges", c.fragment_merges},
          {"point_tests", c.point_tests},
          {"grid_cells_visited", c.cells_visited},  // grid cells or BVH nodes: the accelerator's steps
          {"rays_terminated_early", c.rays_terminated_early},
          {"fragments", c.fragments},
          {"peak_abuffer_length", c.peak_fragments},
          {"rays_pruned_by_contribution", c.pruned_rays},
          {"secondary_by_kind", by_kind(c)}};
}

// Where the scene's memory goes: the curve segments, the acceleration structure, and the
// process's peak resident size so far (parsing, building and rendering included).
nlohmann::json memory_json(const Scene& scene) {
  const size_t segments = scene.curves.size();
  const size_t curve_bytes = scene.curves.memory_bytes(), accel_bytes = scene.accel.memory_bytes();
  return {{"curve_bytes", curve_bytes},
          {"accelerator_bytes", accel_bytes},
          {"bytes_per_segment", segments ? double(curve_bytes + accel_bytes) / double(segments) : 0.0},
          {"peak_resident_bytes", peak_resident_bytes()}};
}

// "" when `image` may be written to `file` and leave the disk reserve free; else the error.
std::string disk_reserve_refusal(const AppOptions& o, const std::string& file, const Image& image) {
  if (o.disk_reserve_bytes && *o.disk_reserve_bytes == 0) return {};
  const fs::path folder = fs::path(file).parent_path();
  const std::optional<DiskSpace> space = disk_space(folder.empty() ? "." : folder.string());
  if (!space) return {};  // no such folder: the write fails on its own
  const uint64_t reserve = o.disk_reserve_bytes ? *o.disk_reserve_bytes : default_disk_reserve(*space);
  const std::string source = o.disk_reserve_bytes
                                 ? "--disk-reserve"
                                 : "the default, 1 % of the file system up to 1 GB; --disk-reserve changes it";
  const std::string shortfall = disk_reserve_shortfall(*space, image_file_bound(image.pixels.size()), reserve, source);
  return shortfall.empty() ? shortfall : file + ": " + shortfall;
}

// write_image, unless the write would leave less than the disk reserve free (then nothing is
// written).
WriteResult write_within_reserve(const AppOptions& o, const std::string& file, const Image& image,
                                 const ImageMetadata& meta, const ColorConfig& colors, const std::string& mode) {
  WriteResult refused;
  refused.error = disk_reserve_refusal(o, file, image);
  if (refused.error.empty()) return write_image(file, image, meta, colors, mode);
  refused.ok = false;
  return refused;
}

}  // namespace

FrameSession::FrameSession(const AppOptions& options, const ColorConfig& colors, Diagnostics& diag,
                           ProgressReporter& progress, const ArchiveCache* archives)
    : o_(options),
      colors_(colors),
      diag_(diag),
      progress_(progress),
      archives_(archives),
      stats_per_frame_(has_frame_number_pattern(options.stats_path)) {}

SceneBuilder::Callbacks FrameSession::callbacks() {
  SceneBuilder::Callbacks cb;
  if (o_.frames)
    cb.frame_selected = [this](int f) {
      const bool selected = o_.frames->contains(f);
      if (selected) ++frames_seen_;
      return selected;
    };
  cb.frame_failed = [this](int) { segment_start_ = Clock::now(); };
  cb.frame_ready = [this](Scene&& scene) { frame_ready(std::move(scene)); };
  return cb;
}

nlohmann::json FrameSession::run_stats() const {
  const bool enabled = archives_ != nullptr && o_.archive_cache;
  return nlohmann::json{{"archive_cache",
                         {{"enabled", enabled},
                          {"archives_parsed", archives_ ? archives_->parses() : 0},
                          {"archives_replayed", archives_ ? archives_->replays() : 0}}}};
}

void FrameSession::frame_ready(Scene&& scene) {
  FrameStats stats;
  stats.parse_seconds = seconds_since(segment_start_);
  const std::string path = output_path(o_, scene.output);
  if (o_.skip_existing) {
    const ExistingFrame existing = existing_frame(path);
    if (existing == ExistingFrame::Done) {
      if (!o_.quiet)
        std::fprintf(stderr, "darc: %s exists: frame %d skipped\n", path.c_str(), scene.output.frame_number);
      segment_start_ = Clock::now();
      progress_.skip_frame();
      return;
    }
    if (existing == ExistingFrame::HasErrors && !o_.quiet)
      std::fprintf(stderr, "darc: %s exists but records errors: frame %d rendered again\n", path.c_str(),
                   scene.output.frame_number);
  }
  if (written_.count(path))
    std::fprintf(stderr, "darc: warning: frame %d overwrites %s (use '#' or %%04d in the name)\n",
                 scene.output.frame_number, path.c_str());
  Clock::time_point t0 = Clock::now();
  const bool reused = acceleration_.build(scene);
  stats.build_seconds = seconds_since(t0);

  RenderOptions ro;
  ro.hider = o_.hider;
  ro.threads = o_.threads;
  ro.seed = o_.seed;
  if (o_.contribution_threshold) ro.contribution_threshold = *o_.contribution_threshold;
  ro.distance.area_light_cones = o_.area_light_cones;
  ro.progress = [&](double f) { progress_.update(f); };
  progress_.start(path);
  Image image = render_frame(scene, ro, diag_, stats);
  progress_.finish();

  ImageMetadata meta;
  meta.software = std::string("darc ") + DARC_VERSION;
  meta.hider = to_string(o_.hider);
  meta.samples_per_pixel = int(scene.output.pixel_samples[0] * scene.output.pixel_samples[1]);
  meta.render_seconds = float(stats.render_seconds);
  const FrameErrors& frame_errors = diag_.frame_errors();  // the requests this frame was rendered without
  meta.error_count = frame_errors.count;
  meta.first_error = frame_errors.first;
  WriteResult wr = write_within_reserve(o_, path, image, meta, colors_, scene.output.display_mode);
  for (const std::string& w : wr.warnings) std::fprintf(stderr, "darc: warning: %s: %s\n", path.c_str(), w.c_str());
  if (wr.nonfinite_replaced > 0)
    std::fprintf(stderr, "darc: warning: %lld non-finite values written as 0 in %s\n",
                 static_cast<long long>(wr.nonfinite_replaced), path.c_str());
  if (!wr.ok) {
    std::fprintf(stderr, "darc: error: cannot write %s: %s\n", path.c_str(), wr.error.c_str());
    io_error_ = true;
  } else {
    written_.insert(path);
    if (!o_.quiet && frame_errors.count > 0)
      std::fprintf(stderr, "darc: wrote %s with %lld scene errors (recorded as %s in it)\n", path.c_str(),
                   static_cast<long long>(frame_errors.count), kErrorCountAttribute);
    else if (!o_.quiet)
      std::fprintf(stderr, "darc: wrote %s\n", path.c_str());
  }
  if (!o_.preview.empty()) {
    std::string pv = substitute_frame_number(o_.preview, scene.output.frame_number);
    WriteResult pr = write_within_reserve(o_, pv, image, meta, colors_, "rgba");
    if (!pr.ok) {
      std::fprintf(stderr, "darc: error: cannot write %s: %s\n", pv.c_str(), pr.error.c_str());
      io_error_ = true;
    }
  }
  nlohmann::json frame_stats{{"frame", scene.output.frame_number},
                             {"output", path},
                             {"hider", to_string(o_.hider)},
                             {"resolution", {scene.output.xres, scene.output.yres}},
                             {"pixel_samples", {scene.output.pixel_samples[0], scene.output.pixel_samples[1]}},
                             {"curve_segments", scene.curves.size()},
                             {"accelerator", to_string(scene.accel.kind())},
                             {"accelerator_reused", reused},
                             {"memory", memory_json(scene)},
                             {"parse_seconds", stats.parse_seconds},
                             {"build_seconds", stats.build_seconds},
                             {"render_seconds", stats.render_seconds},
                             {"counters", counters_json(stats.counters)}};
  if (!scene.output.integrator.empty()) frame_stats["integrator"] = integrator_json(scene.output.integrator);
  if (stats_per_frame_) {
    const std::string stats_path = substitute_frame_number(o_.stats_path, scene.output.frame_number);
    const std::string error = write_stats_file(stats_path, nlohmann::json::array({std::move(frame_stats)}), run_stats());
    if (!error.empty()) {
      std::fprintf(stderr, "darc: error: cannot write %s: %s\n", stats_path.c_str(), error.c_str());
      io_error_ = true;
    }
  } else {
    stats_frames_.push_back(std::move(frame_stats));
  }
  segment_start_ = Clock::now();
}

bool FrameSession::finish() {
  if (!o_.stats_path.empty() && !stats_per_frame_) {
    const std::string error = write_stats_file(o_.stats_path, stats_frames_, run_stats());
    if (!error.empty()) {
      std::fprintf(stderr, "darc: error: cannot write %s: %s\n", o_.stats_path.c_str(), error.c_str());
      io_error_ = true;
    }
  }
  return !io_error_;
}

}  // namespace darc
