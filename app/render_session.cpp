#include "app/render_session.h"

#include "app/frame_count.h"
#include "app/frame_session.h"
#include "app/memory_limit.h"
#include "app/process_memory.h"
#include "app/progress_reporter.h"
#include "core/scene/frame_memory.h"
#include "core/scene/builder/scene_builder.h"
#include "integrator/color_config.h"
#include "parser/rib_parser.h"
#include "parser/rib_writer.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <optional>

namespace darc {

namespace {

namespace fs = std::filesystem;

// The caps on printed messages (message_budget.h) are summed up once, after everything else.
void print_suppression_summary(const Diagnostics& diag) {
  for (const std::string& line : diag.suppression_summary()) std::fprintf(stderr, "darc: %s\n", line.c_str());
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
  ArchiveCache archives;  // each archive parsed once for the run (--no-archive-cache: off)
  FrameSession frames(o, colors, diag, progress, &archives);

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
  SceneBuilder builder(diag, frames.callbacks(), overrides);
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
  if (o.frames && frames.frames_seen() == 0)
    std::fprintf(stderr, "darc: warning: --frames selected none of the frames in the input\n");
  print_suppression_summary(diag);

  const bool written = frames.finish();
  if (diag.error_count() > 0) return kExitSceneError;
  return written ? kExitOk : kExitRenderError;
}

}  // namespace darc
