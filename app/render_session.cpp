#include "app/render_session.h"

#include "app/frame_count.h"
#include "app/frame_session.h"
#include "app/run_limits.h"
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
  overrides.crop = o.crop;
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
