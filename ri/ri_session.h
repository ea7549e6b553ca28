// One RenderMan Interface session, from Begin to End, behind the C binding (ri.h) and the Python
// module (python/): where the requests go and the interface's own state.
//
// Requests go to one of two targets: a SceneBuilder whose frames are rendered and written as the
// darc command renders them (app/frame_session.h, with the command's default settings), or a
// RibWriter into a RIB file (written beside its name and renamed at End, so that no half-written
// file is left) or standard output. The requests the RIB parser keeps state for (Declare, Option,
// Attribute, FrameBegin, ReadArchive, procedurals) reach the target through a RibParser, as the
// RIB text of that one request, so that declarations, search paths, inline archives and the
// frame number conditions see behave as in a RIB file; every other request, geometry first,
// goes straight to the target with its values.
#pragma once

#include "app/app_options.h"
#include "app/frame_session.h"
#include "app/progress_reporter.h"
#include "core/scene/builder/scene_builder.h"
#include "integrator/color_config.h"
#include "parser/archive_cache.h"
#include "parser/diagnostics.h"
#include "parser/rib_parser.h"
#include "parser/rib_writer.h"
#include "ri/basis_steps.h"

#include <array>
#include <fstream>
#include <functional>
#include <memory>
#include <optional>
#include <string>

namespace darc {

class RiSession {
 public:
  // `name`: "" (or "darc", or "darc ARGS" with the darc command's options, e.g. "darc --hider
  // stochastic --pixel-samples 4") renders in this process; "-" writes RIB to standard output;
  // anything else is the RIB file to write. `sink` receives every diagnostic the error handler
  // lets through.
  // Throws std::runtime_error when the output cannot be opened or no colour configuration is found.
  RiSession(const std::string& name, Diagnostics::Sink sink);
  ~RiSession();
  RiSession(const RiSession&) = delete;
  RiSession& operator=(const RiSession&) = delete;

  // Where requests go (through the basis-step tracker).
  RiTarget& target() { return steps_; }
  Diagnostics& diagnostics() { return diag_; }
  bool rendering() const { return builder_ != nullptr; }
  // An error arrived under the abort handler: every later request is ignored.
  bool stopped() const { return diag_.aborted(); }

  // The position of the next call of the C binding: "<ri call N>:1:1".
  SourceLoc next_call();

  // The requests that pass through the parser, as the RIB text of the one request (see above).
  void declare(const std::string& name, const std::string& declaration, const SourceLoc& loc);
  void option(const std::string& category, const ParamList& params, const SourceLoc& loc);
  void attribute(const std::string& category, const ParamList& params, const SourceLoc& loc);
  void frame_begin(int number, const SourceLoc& loc);
  void read_archive(const std::string& name, const SourceLoc& loc);
  void delayed_read_archive(const std::string& file, const std::array<double, 6>& bound, const SourceLoc& loc);
  void run_program(const std::string& program, const std::string& argument, const std::array<double, 6>& bound,
                   const SourceLoc& loc);
  // ErrorHandler "ignore", "print" or "abort": written to a RIB file, applied to the diagnostics.
  void error_handler(const std::string& name, const SourceLoc& loc);
  // A procedural of the program's own: asks the frame about the bound (in the current object
  // space) and, when it can reach the image, calls `subdivide` with the bound's area in pixels
  // (0: unknown) inside an attribute block, as the parser expands a procedural.
  void expand_procedural(const std::array<double, 6>& bound, const std::function<void(double detail)>& subdivide,
                         const SourceLoc& loc);
  // The type of a parameter named without an inline declaration: Declare'd, else standard.
  std::optional<ParamDecl> declared_type(const std::string& name) const;

  int ustep() const { return steps_.ustep(); }
  int vstep() const { return steps_.vstep(); }
  // Handles for lights and objects: "1", "2", ... in the order they are made.
  std::string next_handle() { return std::to_string(++handles_); }

  // Ends the session: an open frame is closed as the end of a RIB file closes it, the run's
  // files are finished. Returns false when a file could not be written. Called once; the
  // destructor ends a session that was not ended.
  bool end();

 private:
  Diagnostics diag_;
  // Rendering.
  AppOptions options_;
  std::optional<ColorConfig> colors_;
  ProgressReporter progress_;
  ArchiveCache archives_;
  std::unique_ptr<FrameSession> frames_;
  std::unique_ptr<SceneBuilder> builder_;
  // Writing RIB.
  std::string rib_path_, rib_temp_path_;
  std::ofstream rib_file_;
  std::unique_ptr<RibWriter> writer_;

  BasisSteps steps_;
  RibParser parser_;
  long long calls_ = 0;
  int handles_ = 0;
  bool ended_ = false;

  RiTarget& make_target(const std::string& name);
  void parse_request(std::string rib_text, const SourceLoc& loc);
};

}  // namespace darc
