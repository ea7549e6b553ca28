#include "app/render_session.h"

#include "app/disk_reserve.h"
#include "app/frame_count.h"
#include "app/memory_limit.h"
#include "app/process_memory.h"

#include "app/progress_reporter.h"
#include "app/stats_file.h"
#include "core/scene/acceleration_reuse.h"
#include "core/scene/frame_memory.h"
#include "core/scene/builder/scene_builder.h"
#include "integrator/color_config.h"
#include "integrator/image_writer.h"
#include "integrator/render_frame.h"
#include "parser/rib_parser.h"
#include "parser/rib_writer.h"

#include <nlohmann/json.hpp>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <optional>
#include <set>

namespace darc {

namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

// --skip-existing: a frame counts as done when its file exists, its header opens and it records
// no errors (a frame rendered without some of its requests is rendered again).
enum class ExistingFrame { Missing, Done, HasErrors };

ExistingFrame existing_frame(const std::string& path) {
  if (!fs::exists(path)) return ExistingFrame::Missing;
  const std::optional<std::int64_t> errors = read_recorded_error_count(path);
  if (!errors) return ExistingFrame::Missing;  // unreadable: render it again
  return *errors > 0 ? ExistingFrame::HasErrors : ExistingFrame::Done;
}

// The caps on printed messages (message_budget.h) are summed up once, after everything else.
void print_suppression_summary(const Diagnostics& diag) {
  for (const std::string& line : diag.suppression_summary()) std::fprintf(stderr, "darc: %s\n", line.c_str());
}

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

// The memory the whole run may use: --memory-limit, else what Linux allows; nullopt for none.
std::optional<MemoryLimit> run_memory_limit(const AppOptions& o) {
  if (o.memory_limit_bytes) {
    if (*o.memory_limit_bytes == 0) return std::nullopt;  // --memory-limit none
    return MemoryLimit{*o.memory_limit_bytes, "--memory-limit"};
  }
  std::optional<MemoryLimit> system = memory_limit(this_process_memory_inputs());
  if (system) system->source += "; --memory-limit changes it";
  return system;
}

// No RIB text (an input, an archive, a .gz once decompressed) may be larger than the memory the
// run may use: it could not be held, and a file that never ends or a gzip bomb stops here.
std::uint64_t text_limit_bytes(const AppOptions& o) {
  const std::optional<MemoryLimit> limit = run_memory_limit(o);
  return limit ? limit->bytes : 0;
}

void set_text_limit(const AppOptions& o, RibParser& parser) {
  if (const std::optional<MemoryLimit> limit = run_memory_limit(o))
    parser.set_text_limit(limit->bytes, "the memory limit, from " + limit->source);
}

// The part of the memory limit a frame's geometry may take (SceneBuilder checks its estimate):
// what the process may hold, less what it holds now and twice the largest input file (the parser
// holds a file's text while its frames are built; a gzip file's text is larger than the file,
// which the factor of two roughly covers).
void set_frame_memory_limit(const AppOptions& o, FrameOverrides& overrides) {
  const std::optional<MemoryLimit> process_limit = run_memory_limit(o);
  if (!process_limit) return;
  const MemoryLimit& limit = *process_limit;
  const MemoryLimitInputs now = this_process_memory_inputs();
  uint64_t text = 0;
  for (const std::string& in : o.inputs) {
    std::error_code ec;
    if (in != "-") text = std::max<uint64_t>(text, fs::file_size(in, ec) * (ec ? 0 : 1));
  }
  const uint64_t held = now.process_resident + 2 * text;
  overrides.memory_limit_bytes = limit.bytes > held ? limit.bytes - held : 1;
  overrides.memory_limit_source = "the limit is " + format_bytes(limit.bytes) + ", from " + limit.source;
}

// The user's procedural folders (--procedural-path, then DARC_PROCEDURAL_PATH), --trust-rib and
// --procedural-timeout. A folder of the variable that does not exist is reported and left out
// (--procedural-path checks its own as a usage error).
void configure_procedurals(const AppOptions& o, RibParser& parser) {
  std::vector<std::string> folders = o.procedural_paths;
  for (const std::string& dir : o.procedural_env_paths) {
    std::error_code ec;
    if (fs::is_directory(dir, ec)) folders.push_back(dir);
    else std::fprintf(stderr, "darc: warning: DARC_PROCEDURAL_PATH: \"%s\" is not a folder: ignored\n", dir.c_str());
  }
  parser.set_procedural_folders(folders);
  parser.set_trust_rib(o.trust_rib);
  RunProgramLimits limits;
  limits.time_limit = std::chrono::milliseconds(std::llround(o.procedural_timeout_seconds * 1000));
  parser.set_run_program_limits(limits);
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

int run_render_session(const AppOptions& o) {
  Diagnostics diag;
  if (o.strict) diag.fix_handler(ErrorHandler::Abort);
  for (const std::string& in : o.inputs) {
    if (in == "-") continue;
    std::error_code ec;
    const fs::file_status status = fs::status(in, ec);
    if (!fs::exists(status)) {
      std::fprintf(stderr, "darc: input file \"%s\" does not exist\n", in.c_str());
      return kExitUsage;
    }
    // A directory opens as a stream that reads nothing, which would render nothing silently.
    if (fs::is_directory(status)) {
      std::fprintf(stderr, "darc: input \"%s\" is a directory, not a RIB file\n", in.c_str());
      return kExitUsage;
    }
  }

  if (o.cat) {
    RibWriter writer(std::cout);
    RibParser parser(writer, diag);
    configure_procedurals(o, parser);
    set_text_limit(o, parser);
    for (const std::string& in : o.inputs) {
      if (diag.aborted()) break;
      parser.parse_file(in);
    }
    print_suppression_summary(diag);
    return diag.error_count() > 0 ? kExitSceneError : kExitOk;
  }

  ColorConfigLookup lookup = find_color_config(o.ocio_config);
  if (!lookup.config) {
    std::fprintf(stderr, "darc: error: %s\n", lookup.error.c_str());
    return kExitUsage;
  }
  const ColorConfig& colors = *lookup.config;
  ProgressReporter progress(o.progress || !o.quiet, isatty(STDERR_FILENO) != 0);
  if (o.progress || !o.quiet) progress.set_frames_in_run(count_frames(o.inputs, o.frames, text_limit_bytes(o)).value_or(0));
  nlohmann::json stats_frames = nlohmann::json::array();
  // "--stats stats/f.####.json": each frame's entry goes to a file of its own as soon as the frame
  // is written, so a sequence stopped part-way (a farm task cancelled) keeps the stats it made.
  const bool stats_per_frame = has_frame_number_pattern(o.stats_path);
  bool io_error = false;
  std::set<std::string> written;
  Clock::time_point segment_start = Clock::now();

  AccelerationReuse acceleration;  // a frame with the previous one's geometry keeps its BVH
  ArchiveCache archives;           // each archive parsed once for the run (--no-archive-cache: off)
  auto run_stats = [&] {
    return nlohmann::json{{"archive_cache",
                           {{"enabled", o.archive_cache},
                            {"archives_parsed", archives.parses()},
                            {"archives_replayed", archives.replays()}}}};
  };
  SceneBuilder::Callbacks cb;
  int frames_seen = 0;  // frames --frames selected (rendered, skipped as existing or failed)
  if (o.frames)
    cb.frame_selected = [&](int f) {
      const bool selected = o.frames->contains(f);
      if (selected) ++frames_seen;
      return selected;
    };
  cb.frame_failed = [&](int) { segment_start = Clock::now(); };
  cb.frame_ready = [&](Scene&& scene) {
    FrameStats stats;
    stats.parse_seconds = seconds_since(segment_start);
    const std::string path = output_path(o, scene.output);
    if (o.skip_existing) {
      const ExistingFrame existing = existing_frame(path);
      if (existing == ExistingFrame::Done) {
        if (!o.quiet)
          std::fprintf(stderr, "darc: %s exists: frame %d skipped\n", path.c_str(), scene.output.frame_number);
        segment_start = Clock::now();
        progress.skip_frame();
        return;
      }
      if (existing == ExistingFrame::HasErrors && !o.quiet)
        std::fprintf(stderr, "darc: %s exists but records errors: frame %d rendered again\n", path.c_str(),
                     scene.output.frame_number);
    }
    if (written.count(path))
      std::fprintf(stderr, "darc: warning: frame %d overwrites %s (use '#' or %%04d in the name)\n",
                   scene.output.frame_number, path.c_str());
    Clock::time_point t0 = Clock::now();
    const bool reused = acceleration.build(scene);
    stats.build_seconds = seconds_since(t0);

    RenderOptions ro;
    ro.hider = o.hider;
    ro.threads = o.threads;
    ro.seed = o.seed;
    if (o.contribution_threshold) ro.contribution_threshold = *o.contribution_threshold;
    ro.progress = [&](double f) { progress.update(f); };
    progress.start(path);
    Image image = render_frame(scene, ro, diag, stats);
    progress.finish();

    ImageMetadata meta;
    meta.software = std::string("darc ") + DARC_VERSION;
    meta.hider = to_string(o.hider);
    meta.samples_per_pixel = int(scene.output.pixel_samples[0] * scene.output.pixel_samples[1]);
    meta.render_seconds = float(stats.render_seconds);
    const FrameErrors& frame_errors = diag.frame_errors();  // the requests this frame was rendered without
    meta.error_count = frame_errors.count;
    meta.first_error = frame_errors.first;
    WriteResult wr = write_within_reserve(o, path, image, meta, colors, scene.output.display_mode);
    for (const std::string& w : wr.warnings) std::fprintf(stderr, "darc: warning: %s: %s\n", path.c_str(), w.c_str());
    if (wr.nonfinite_replaced > 0)
      std::fprintf(stderr, "darc: warning: %lld non-finite values written as 0 in %s\n",
                   static_cast<long long>(wr.nonfinite_replaced), path.c_str());
    if (!wr.ok) {
      std::fprintf(stderr, "darc: error: cannot write %s: %s\n", path.c_str(), wr.error.c_str());
      io_error = true;
    } else {
      written.insert(path);
      if (!o.quiet && frame_errors.count > 0)
        std::fprintf(stderr, "darc: wrote %s with %lld scene errors (recorded as %s in it)\n", path.c_str(),
                     static_cast<long long>(frame_errors.count), kErrorCountAttribute);
      else if (!o.quiet)
        std::fprintf(stderr, "darc: wrote %s\n", path.c_str());
    }
    if (!o.preview.empty()) {
      std::string pv = substitute_frame_number(o.preview, scene.output.frame_number);
      WriteResult pr = write_within_reserve(o, pv, image, meta, colors, "rgba");
      if (!pr.ok) {
        std::fprintf(stderr, "darc: error: cannot write %s: %s\n", pv.c_str(), pr.error.c_str());
        io_error = true;
      }
    }
    nlohmann::json frame_stats{{"frame", scene.output.frame_number},
                               {"output", path},
                               {"hider", to_string(o.hider)},
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
    if (stats_per_frame) {
      const std::string stats_path = substitute_frame_number(o.stats_path, scene.output.frame_number);
      const std::string error = write_stats_file(stats_path, nlohmann::json::array({std::move(frame_stats)}), run_stats());
      if (!error.empty()) {
        std::fprintf(stderr, "darc: error: cannot write %s: %s\n", stats_path.c_str(), error.c_str());
        io_error = true;
      }
    } else {
      stats_frames.push_back(std::move(frame_stats));
    }
    segment_start = Clock::now();
  };

  FrameOverrides overrides;
  overrides.xres = o.xres;
  overrides.yres = o.yres;
  overrides.pixel_samples = o.pixel_samples;
  set_frame_memory_limit(o, overrides);
  // -o is the user's; without it, the RIB's Display names stay in the working folder unless the
  // user trusts the RIB.
  if (o.output.empty() && !o.trust_rib) {
    std::error_code ec;
    const fs::path here = fs::canonical(fs::current_path(ec), ec);
    if (ec) {
      std::fprintf(stderr, "darc: error: cannot resolve the working folder (%s), where Display names must stay\n",
                   ec.message().c_str());
      return kExitRenderError;
    }
    overrides.display_folder = here.string();
  }
  SceneBuilder builder(diag, cb, overrides);
  RibParser parser(builder, diag);
  if (o.archive_cache) parser.use_archive_cache(&archives);
  configure_procedurals(o, parser);
  set_text_limit(o, parser);
  for (const std::string& in : o.inputs) {
    if (diag.aborted()) break;
    parser.parse_file(in);
  }
  builder.finish(SourceLoc{});
  if (diag.aborted())
    std::fprintf(stderr, "darc: stopped at the first error (%s)\n", o.strict ? "--strict" : "ErrorHandler \"abort\"");
  if (o.frames && frames_seen == 0)
    std::fprintf(stderr, "darc: warning: --frames selected none of the frames in the input\n");
  print_suppression_summary(diag);

  if (!o.stats_path.empty() && !stats_per_frame) {
    const std::string error = write_stats_file(o.stats_path, stats_frames, run_stats());
    if (!error.empty()) {
      std::fprintf(stderr, "darc: error: cannot write %s: %s\n", o.stats_path.c_str(), error.c_str());
      io_error = true;
    }
  }
  if (diag.error_count() > 0) return kExitSceneError;
  return io_error ? kExitRenderError : kExitOk;
}

}  // namespace darc
