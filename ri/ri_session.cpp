#include "ri/ri_session.h"

#include "app/run_limits.h"
#include "parser/standard_declarations.h"

#include <unistd.h>

#include <sstream>
#include <vector>

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <stdexcept>

namespace darc {

namespace {

namespace fs = std::filesystem;

// "darc" or "darc ARGS": rendering in this process, with the darc command's options ARGS
// (split at blanks; no quoting) for the session, as if the requests were a RIB file on that
// command line.
bool is_render_name(const std::string& name) {
  return name.empty() || name == "darc" || name.rfind("darc ", 0) == 0;
}

// The settings of the session: the darc command's defaults, or the options given after "darc",
// but quiet (a library prints no lines of its own; messages go to the error handler) and
// trusting the program's Display names and procedurals. Throws std::runtime_error on a usage
// error (the parser has printed it) or an option that makes no sense here.
AppOptions session_options(const std::string& name) {
  // Without options too, so that the environment the command reads (DARC_PROCEDURAL_PATH) is read.
  std::vector<std::string> words{"darc"};
  std::istringstream split(name.rfind("darc ", 0) == 0 ? name.substr(5) : std::string());
  for (std::string word; split >> word;) words.push_back(word);
  words.push_back("-");  // the command wants an input: the session's requests are it
  std::vector<char*> argv;
  for (std::string& w : words) argv.push_back(w.data());
  bool exit_now = false;
  int exit_code = 0;
  AppOptions o = parse_command_line(int(argv.size()), argv.data(), exit_now, exit_code);
  if (exit_now) throw std::runtime_error("\"" + name + "\": not a darc command line (see the message above)");
  if (o.inputs.size() != 1) throw std::runtime_error("\"" + name + "\": RIB files cannot be named here");
  if (o.cat) throw std::runtime_error("\"" + name + "\": --cat: RiBegin(\"file.rib\") writes RIB");
  o.inputs.clear();
  o.quiet = true;
  o.trust_rib = true;
  return o;
}
}  // namespace

RiSession::RiSession(const std::string& name, Diagnostics::Sink sink)
    : diag_(std::move(sink)),
      options_(session_options(is_render_name(name) ? name : "")),
      progress_(options_.progress, ::isatty(STDERR_FILENO) != 0),
      steps_(make_target(name)),
      parser_(steps_, diag_) {
  configure_procedurals(options_, parser_);  // trusted: the program's own searchpath holds
  set_text_limit(options_, parser_);
  if (options_.strict) diag_.fix_handler(ErrorHandler::Abort);
  if (rendering() && options_.archive_cache) parser_.use_archive_cache(&archives_);
}

RiTarget& RiSession::make_target(const std::string& name) {
  if (is_render_name(name)) {
    ColorConfigLookup lookup = find_color_config(options_.ocio_config);
    if (!lookup.config) throw std::runtime_error(lookup.error);
    colors_ = std::move(lookup.config);
    frames_ = std::make_unique<FrameSession>(options_, *colors_, diag_, progress_, &archives_);
    FrameOverrides overrides;  // as the command applies --res and --pixel-samples
    overrides.xres = options_.xres;
    overrides.yres = options_.yres;
    overrides.pixel_samples = options_.pixel_samples;
    set_frame_memory_limit(options_, overrides);  // a frame over it fails alone: the program goes on
    builder_ = std::make_unique<SceneBuilder>(diag_, frames_->callbacks(), overrides);
    return *builder_;
  }
  if (name == "-") {
    writer_ = std::make_unique<RibWriter>(std::cout);
    return *writer_;
  }
  rib_path_ = name;
  // Unique to this session: two sessions of one process may write the same name.
  rib_temp_path_ = name + ".part" + std::to_string(::getpid()) + "-" +
                   std::to_string(reinterpret_cast<std::uintptr_t>(this));
  rib_file_.open(rib_temp_path_, std::ios::binary | std::ios::trunc);
  if (!rib_file_) throw std::runtime_error("cannot write " + rib_temp_path_);
  writer_ = std::make_unique<RibWriter>(rib_file_);
  return *writer_;
}

RiSession::~RiSession() {
  if (ended_) return;
  try {
    end();
  } catch (...) {
    std::fprintf(stderr, "darc: error: a RenderMan session could not be ended cleanly\n");
  }
}

SourceLoc RiSession::next_call() {
  ++calls_;
  return SourceLoc{std::make_shared<const std::string>("<ri call " + std::to_string(calls_) + ">"), 1, 1};
}

void RiSession::parse_request(std::string rib_text, const SourceLoc& loc) {
  parser_.parse_request_text(std::move(rib_text), loc);
}

namespace {

// The RIB text of one request as RibWriter writes it.
template <typename Write>
std::string rib_text(Write write) {
  std::ostringstream text;
  RibWriter writer(text);
  write(writer);
  return text.str();
}

std::string bound_text(const std::array<double, 6>& bound) {
  std::string text = "[";
  for (size_t i = 0; i < 6; ++i) {
    if (i > 0) text += ' ';
    text += rib_number(bound[i]);
  }
  text += ']';
  return text;
}

}  // namespace

void RiSession::declare(const std::string& name, const std::string& declaration, const SourceLoc& loc) {
  parse_request(rib_text([&](RibWriter& w) { w.declare(name, declaration, loc); }), loc);
}

void RiSession::option(const std::string& category, const ParamList& params, const SourceLoc& loc) {
  parse_request(rib_text([&](RibWriter& w) { w.option(category, params, loc); }), loc);
}

void RiSession::attribute(const std::string& category, const ParamList& params, const SourceLoc& loc) {
  parse_request(rib_text([&](RibWriter& w) { w.attribute(category, params, loc); }), loc);
}

void RiSession::frame_begin(int number, const SourceLoc& loc) {
  parse_request(rib_text([&](RibWriter& w) { w.frame_begin(number, loc); }), loc);
}

void RiSession::read_archive(const std::string& name, const SourceLoc& loc) {
  parse_request("ReadArchive " + rib_string(name) + "\n", loc);
}

void RiSession::delayed_read_archive(const std::string& file, const std::array<double, 6>& bound,
                                     const SourceLoc& loc) {
  parse_request("Procedural \"DelayedReadArchive\" [" + rib_string(file) + "] " + bound_text(bound) + "\n", loc);
}

void RiSession::run_program(const std::string& program, const std::string& argument,
                            const std::array<double, 6>& bound, const SourceLoc& loc) {
  parse_request("Procedural \"RunProgram\" [" + rib_string(program) + " " + rib_string(argument) + "] " +
                    bound_text(bound) + "\n",
                loc);
}

void RiSession::error_handler(const std::string& name, const SourceLoc& loc) {
  parse_request("ErrorHandler " + rib_string(name) + "\n", loc);
}

void RiSession::expand_procedural(const std::array<double, 6>& bound,
                                  const std::function<void(double detail)>& subdivide, const SourceLoc& loc) {
  const ProceduralBound view = target().procedural_bound(bound, loc);
  if (!view.wanted) return;
  target().attribute_begin(loc);
  try {
    subdivide(view.raster_area);
  } catch (...) {
    try {
      target().attribute_end(loc);  // the block closes whatever the procedural did
    } catch (...) {
      // the procedural's own exception is the one to report
    }
    throw;
  }
  target().attribute_end(loc);
}

std::optional<ParamDecl> RiSession::declared_type(const std::string& name) const {
  const DeclarationMap& declared = parser_.declarations();
  if (auto it = declared.find(name); it != declared.end()) return it->second;
  return standard_declaration(name);
}

bool RiSession::end() {
  if (ended_) return true;
  ended_ = true;
  bool ok = true;
  if (builder_) {
    builder_->finish(SourceLoc{std::make_shared<const std::string>("<ri end>"), 1, 1});
    ok = frames_->finish();
  }
  if (rib_file_.is_open()) {
    rib_file_.close();
    const bool written = !rib_file_.fail();
    std::error_code ec;
    // A file cut short by the abort handler is not left behind, as no image is.
    if (!written || diag_.aborted()) {
      if (!written) std::fprintf(stderr, "darc: error: cannot write %s\n", rib_temp_path_.c_str());
      fs::remove(rib_temp_path_, ec);
      return false;
    }
    fs::rename(rib_temp_path_, rib_path_, ec);
    if (ec) {
      std::fprintf(stderr, "darc: error: cannot write %s: %s\n", rib_path_.c_str(), ec.message().c_str());
      fs::remove(rib_temp_path_, ec);
      return false;
    }
  }
  if (writer_ && rib_path_.empty()) std::cout.flush();
  return ok;
}

}  // namespace darc
