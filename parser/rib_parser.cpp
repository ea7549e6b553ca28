#include "parser/rib_parser.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>

#include "parser/condition_expression.h"
#include "parser/error_handler.h"
#include "parser/known_requests.h"
#include "parser/lexer.h"
#include "parser/request_table.h"
#include "parser/search_path.h"
#include "parser/zip_member.h"

namespace darc {

namespace {

namespace fs = std::filesystem;

// ReadArchive nesting limit: far deeper than any real scene, and stops runaway recursion
// through distinct files (a cycle through the same file is caught separately).
constexpr size_t kMaxArchiveDepth = 64;
// Inline archive reads in one parse (refused ones included) and the bytes of the bodies read: an
// archive that reads another twice, 64 levels deep, is a 3 kB file that would take 2^64 replays.
// At about 3 us a read, the cap costs a second (the fuzzer allows 10 s per input); a crowd of
// 100 000 instances of an inline archive stays below it. Past either cap, ReadArchive of an
// inline archive is an error.
constexpr std::uint64_t kMaxInlineReplays = 250'000;
constexpr std::uint64_t kMaxInlineReplayedBytes = std::uint64_t(1) << 30;

// The file an archive's location lies in: the zip file of "dir/cache.zip!member.rib", else the
// location itself.
std::string archive_file(const std::string& location) {
  const std::optional<ZipMemberName> zip = split_zip_member(location);
  return zip ? zip->zip : location;
}

std::string canonical_name(const std::string& path) {
  std::error_code ec;
  const fs::path p = fs::weakly_canonical(fs::path(path), ec);
  return ec ? path : p.string();
}

bool is_readable_file(const fs::path& p) {
  std::error_code ec;
  return fs::is_regular_file(p, ec);
}

// The search path given by every string of `param`.
std::vector<std::string> search_path(const Param& param, const std::vector<std::string>& previous,
                                     const std::vector<std::string>& defaults) {
  std::vector<std::string> dirs;
  for (const std::string& spec : param.strings) {
    const std::vector<std::string> part = expand_search_path(spec, previous, defaults);
    dirs.insert(dirs.end(), part.begin(), part.end());
  }
  return dirs;
}

}  // namespace

bool RibParser::parse_file(const std::string& path) {
  const int errors_before = diag_.error_count();
  std::string text;
  std::string reason;
  if (!read_rib_text(path, text, reason, text_limits_)) {
    diag_.error(SourceLoc{std::make_shared<const std::string>(path), 0, 0}, "",
                fmt::format("cannot read \"{}\": {}", path, reason));
    return false;
  }
  parse_text(std::move(text), path == "-" ? std::string("<stdin>") : path);
  return diag_.error_count() == errors_before;
}

bool RibParser::parse_string(std::string_view text, const std::string& name) {
  const int errors_before = diag_.error_count();
  parse_text(std::string(text), name);
  return diag_.error_count() == errors_before;
}

bool RibParser::parse_request_text(std::string text, const SourceLoc& at) {
  const int errors_before = diag_.error_count();
  const size_t size = text.size();
  RibTextSpan span{std::make_shared<const std::string>(std::move(text)), 0, size, at.file, std::max(at.line, 1),
                   std::max(at.column, 1)};
  Lexer lexer(span);
  std::error_code ec;
  include_stack_.push_back((fs::current_path(ec) / "<ri>").string());
  // The calling program goes on after an exception (out of memory, its own error handler's):
  // the stack must not keep this entry.
  struct Pop {
    std::vector<std::string>& stack;
    ~Pop() { stack.pop_back(); }
  } pop{include_stack_};
  parse_requests(lexer);
  return diag_.error_count() == errors_before;
}

void RibParser::parse_text(std::string text, const std::string& name) {
  Lexer lexer(std::move(text), std::make_shared<const std::string>(name));
  include_stack_.push_back(canonical_name(name));
  parse_requests(lexer);
  include_stack_.pop_back();
}

void RibParser::parse_requests(Lexer& lexer) {
  RequestReader args(lexer, declared_, diag_);
  TextScope scope{lexer, {}};
  TextScope* const enclosing = scope_;
  scope_ = &scope;
  read_requests(scope, args);
  scope_ = enclosing;
  if (diag_.aborted()) return;
  for (const SourceLoc& open : scope.conditionals.open_blocks())
    diag_.error(open, "IfBegin", "conditional block is never closed (IfEnd missing)");
}

void RibParser::read_requests(TextScope& scope, RequestReader& args) {
  Lexer& lexer = scope.lexer;
  while (true) {
    if (diag_.aborted()) return;  // ErrorHandler "abort": nothing after the first error is read
    const Token& token = lexer.peek();
    if (token.kind == TokenKind::End) return;
    if (token.kind == TokenKind::Error) {
      diag_.error(lexer.loc(token), "", token.text);
      lexer.next();
      continue;
    }
    if (token.kind != TokenKind::Word) {
      diag_.error(lexer.loc(token), "", fmt::format("expected a request name, found {}", describe(token)));
      skip_to_next_request(lexer);
      continue;
    }
    const Token name = lexer.next();
    const SourceLoc loc = lexer.loc(name);
    try {
      if (conditional(name.text, args, loc)) continue;
      if (!scope.conditionals.active()) {
        skip_to_next_request(lexer);  // a branch not taken
        continue;
      }
      dispatch(name.text, args, loc);
    } catch (const RibSyntaxError& e) {
      diag_.error(e.loc, name.text, e.what());
      skip_to_next_request(lexer);
    } catch (const RibError& e) {
      diag_.error(loc, name.text, e.what());
      skip_to_next_request(lexer);
    }
  }
}

void RibParser::skip_to_next_request(Lexer& lexer) {
  while (true) {
    const Token& t = lexer.peek();
    if (t.kind == TokenKind::Word || t.kind == TokenKind::End) return;
    // Lexical errors in skipped text are still errors (a binary byte, an unterminated string).
    if (t.kind == TokenKind::Error) diag_.error(lexer.loc(t), "", t.text);
    lexer.next();
  }
}

void RibParser::dispatch(const std::string& request, RequestReader& args, const SourceLoc& loc) {
  if (request == "ReadArchive") return read_archive(args, loc);
  if (request == "ArchiveBegin") return archive_begin(args, loc);
  if (request == "ArchiveEnd") throw RibError("ArchiveEnd without ArchiveBegin");
  if (request == "Declare") return declare(args, loc);
  if (request == "Option") return option(args, loc);
  if (request == "Attribute") return attribute(args, loc);
  if (request == "FrameBegin") return frame_begin(args, loc);
  if (request == "ErrorHandler") return error_handler(args, loc);
  if (request == "Procedural" || request == "Procedural2") return procedural(args, request, loc);
  if (RequestHandler handler = find_request_handler(request)) {
    RequestContext context{args, target_, loc, request};
    handler(context);
    track_block(request);
    return;
  }
  dispatch_unimplemented(request, args, loc);
}

void RibParser::dispatch_unimplemented(const std::string& request, RequestReader& args, const SourceLoc& loc) {
  if (request == "TrimCurve") {
    // An attribute of the NuPatches that follow (RI Spec 5.4): they are still drawn, whole.
    diag_.warning_once("unsupported request TrimCurve", loc, request,
                       "trim curves are not supported: the untrimmed surface is rendered");
  } else if (const std::optional<KnownRequest> known = find_known_request(request)) {
    diag_.warning_once("unsupported request " + request, loc, request,
                       fmt::format("request \"{}\" ({}) is not supported: skipped", request, describe(known->origin)));
    if (known->kind == RequestKind::Geometry) target_.skipped_primitive(request, loc);
  } else {
    diag_.warning_once("unknown request " + request, loc, request,
                       fmt::format("unknown request \"{}\": skipped", request));
  }
  // Skip the arguments; lexical errors among them are still reported.
  std::vector<double> numbers;
  std::vector<std::string> strings;
  args.flatten_rest(numbers, strings);
}

void RibParser::track_block(const std::string& request) {
  if (request == "FrameEnd") conditions_.frame_end();
  else if (request == "WorldBegin") conditions_.world_begin();
  else if (request == "WorldEnd") conditions_.world_end();
  else if (request == "AttributeBegin") conditions_.attribute_begin();
  else if (request == "AttributeEnd") conditions_.attribute_end();
}

bool RibParser::conditional(const std::string& request, RequestReader& args, const SourceLoc& loc) {
  if (request == "IfBegin" || request == "ElseIf" || request == "Else" || request == "IfEnd") read_parser_state_ = true;
  ConditionalBlocks& blocks = scope_->conditionals;
  if (request == "IfBegin" || request == "ElseIf") {
    // A malformed IfBegin or ElseIf still opens its branch (as one whose condition cannot be
    // evaluated), so that the rest of the block keeps its structure.
    std::string expression;
    bool readable = true;
    std::optional<RibSyntaxError> error;
    try {
      expression = args.string("the condition");
      args.skip_param_list(request);
    } catch (const RibSyntaxError& e) {
      readable = false;
      error = e;
    }
    const auto condition = [&] { return !readable || condition_holds(expression, loc, request); };
    if (request == "IfBegin") {
      blocks.if_begin(loc, condition);
    } else {
      blocks.else_if(condition);
    }
    if (error) throw *error;
    return true;
  }
  // The block changes before stray arguments are reported, so that they do not break it.
  if (request == "Else") {
    blocks.else_branch();
    args.expect_request_end("Else");
    return true;
  }
  if (request == "IfEnd") {
    blocks.if_end();
    args.expect_request_end("IfEnd");
    return true;
  }
  return false;
}

bool RibParser::condition_holds(const std::string& expression, const SourceLoc& loc, const std::string& request) {
  const ConditionOutcome outcome =
      evaluate_condition(expression, [this](std::string_view name) { return conditions_.lookup(name); });
  if (outcome.evaluated()) return outcome.value;
  diag_.warning_once("condition " + expression, loc, request,
                     fmt::format("cannot evaluate \"{}\" ({}): this branch is taken, no later one of its block",
                                 expression, outcome.failure));
  return true;
}

void RibParser::archive_begin(RequestReader& args, const SourceLoc& loc) {
  read_parser_state_ = true;
  const std::string name = args.string("the archive name");
  args.skip_param_list("ArchiveBegin");
  Lexer& lexer = scope_->lexer;
  const ArchiveBodyScan scan = scan_archive_body(lexer);
  if (!scan.closed) {
    if (scan.lexical_error) diag_.error(lexer.loc(*scan.lexical_error), "", scan.lexical_error->text);
    throw RibError(fmt::format("archive \"{}\" is never closed (ArchiveEnd missing)", name));
  }
  inline_archives_.define(name, InlineArchive{scan.body, loc});
}

void RibParser::declare(RequestReader& args, const SourceLoc& loc) {
  const std::string name = args.string("the parameter name");
  const std::string text = args.string("the declaration");
  args.expect_request_end("Declare");
  const std::optional<ParamDecl> decl = parse_param_decl(text);
  if (!decl) throw RibError(fmt::format("invalid declaration \"{}\" for \"{}\"", text, name));
  declared_[name] = *decl;
  target_.declare(name, to_string(*decl), loc);
}

void RibParser::option(RequestReader& args, const SourceLoc& loc) {
  const std::string category = args.string("the option category");
  const ParamList params = args.param_list("Option");
  if (category == "searchpath") {
    if (const Param* archive = params.find("archive")) archive_path_ = search_path(*archive, archive_path_, {});
    if (const Param* procedural = params.find("procedural")) {
      // Relative folders are taken from the file that names them, so that a scene and its
      // generators move together.
      const fs::path base = include_stack_.empty() ? fs::path() : fs::path(include_stack_.back()).parent_path();
      std::vector<std::string> dirs = search_path(*procedural, procedural_search_path(), procedural_folders_);
      for (std::string& dir : dirs)
        if (fs::path(dir).is_relative()) dir = (base / dir).string();
      set_procedural_search_path(dirs, loc);
    }
  }
  target_.option(category, params, loc);
  conditions_.option(category, params);
}

void RibParser::attribute(RequestReader& args, const SourceLoc& loc) {
  const std::string category = args.string("the attribute category");
  const ParamList params = args.param_list("Attribute");
  target_.attribute(category, params, loc);
  conditions_.attribute(category, params);
}

void RibParser::frame_begin(RequestReader& args, const SourceLoc& loc) {
  // The frame number is required by the spec, but some exporters leave it out.
  const int number = args.at_request_end() ? 0 : args.integer("the frame number");
  args.expect_request_end("FrameBegin");
  target_.frame_begin(number, loc);
  conditions_.frame_begin(number);
}

void RibParser::error_handler(RequestReader& args, const SourceLoc& loc) {
  const std::string name = args.string("the handler name");
  args.expect_request_end("ErrorHandler");
  // The target sees it as a request without effect on the image (RibWriter writes it back).
  target_.ignored_request("ErrorHandler", {}, {name}, loc);
  const std::optional<ErrorHandler> handler = error_handler_named(name);
  if (!handler) {
    diag_.warning(loc, "ErrorHandler",
                  fmt::format("unknown handler \"{}\" (expected ignore, print or abort): keeping \"{}\"", name,
                              to_string(diag_.handler())));
    return;
  }
  if (!diag_.set_handler(*handler))
    diag_.warning_once("ErrorHandler fixed", loc, "ErrorHandler",
                       fmt::format("ErrorHandler \"{}\" ignored: the command line fixed the handler to \"{}\"", name,
                                   to_string(diag_.handler())));
}

std::string RibParser::resolve_archive(const std::string& name) const {
  const fs::path given(name);
  if (given.is_absolute()) return name;
  if (!include_stack_.empty()) {
    const fs::path beside = fs::path(archive_file(include_stack_.back())).parent_path() / given;
    if (is_readable_file(beside)) return beside.string();
  }
  for (const std::string& dir : archive_path_) {
    const fs::path candidate = fs::path(dir) / given;
    if (is_readable_file(candidate)) return candidate.string();
  }
  return name;
}

void RibParser::read_archive(RequestReader& args, const SourceLoc& loc) {
  const std::string name = args.string("the archive name");
  args.expect_request_end("ReadArchive");
  include_archive(name, loc);
}

void RibParser::include_archive(const std::string& name, const SourceLoc& loc) {
  if (const InlineArchive* archive = inline_archives_.find(name)) return replay_inline_archive(name, *archive);
  if (!archive_files_allowed_)
    throw RibSyntaxError(loc, fmt::format("cannot open archive \"{}\": file access is disabled", name));
  // A member of a zip file (RenderMan for Maya's caches): the zip is found as a file archive is,
  // and the member read from it (parser/zip_member.h). Its location is "zip path!member".
  const std::optional<ZipMemberName> zip = split_zip_member(name);
  const std::string path = zip ? resolve_archive(zip->zip) + "!" + zip->member : resolve_archive(name);
  std::error_code ec;
  if (!fs::exists(archive_file(path), ec))
    throw RibSyntaxError(loc, fmt::format("cannot open archive \"{}\": no such {}", name, zip ? "zip file" : "file"));
  const std::string canonical = canonical_name(path);
  if (std::find(include_stack_.begin(), include_stack_.end(), canonical) != include_stack_.end()) {
    throw RibSyntaxError(loc, fmt::format("archive \"{}\" includes itself (cycle through {})", name, canonical));
  }
  if (include_stack_.size() >= kMaxArchiveDepth) {
    throw RibSyntaxError(loc, fmt::format("archive \"{}\" is nested deeper than {} levels", name, kMaxArchiveDepth));
  }
  // An archive that cannot be read is an error at the request that named it (the RibError of
  // read_archive_text is reported where that request stands).
  if (archive_cache_) return include_cached_archive(name, path, canonical);
  parse_text(read_archive_text(name, path), path);
}

std::string RibParser::read_archive_text(const std::string& name, const std::string& path) const {
  RibReadLimits limits = text_limits_;
  limits.regular_files_only = true;
  std::string text;
  std::string reason;
  const std::optional<ZipMemberName> zip = split_zip_member(path);
  if (zip ? !read_zip_member(zip->zip, zip->member, text, reason, limits) : !read_rib_text(path, text, reason, limits))
    throw RibError(fmt::format("cannot open archive \"{}\": {}", name, reason));
  // A file that is not RIB (a password file, a key, a shell profile) would come out a token at
  // a time in "unknown request" messages: it is refused whole, and nothing of it is quoted.
  const std::optional<std::string_view> first = leading_word(text);
  if (first && !find_known_request(*first) && !find_request_handler(*first))
    throw RibError(fmt::format("cannot read archive \"{}\": it does not begin with a RIB request, so it is not RIB "
                               "text (or is binary RIB, which is not supported); nothing of it is read",
                               name));
  return text;
}

void RibParser::include_cached_archive(const std::string& name, const std::string& path,
                                       const std::string& canonical) {
  std::shared_ptr<const RecordedArchive> archive = archive_cache_->find(canonical, declared_, archive_path_);
  if (archive) {
    archive_cache_->count_replay();
  } else {
    const std::optional<FileStamp> stamp = stamp_file(archive_file(path));
    std::string text = read_archive_text(name, path);
    std::optional<RecordedArchive> recorded = record_archive(text, path);
    if (!recorded) {
      // Not replayable: parse it as without a cache (the file was read once more for nothing).
      if (recorded_files_ && stamp) recorded_files_->push_back(*stamp);
      parse_text(std::move(text), path);
      return;
    }
    archive = archive_cache_->store(canonical, std::move(*recorded));
  }
  if (recorded_files_) recorded_files_->insert(recorded_files_->end(), archive->files.begin(), archive->files.end());
  replay(*archive);
}

std::optional<RecordedArchive> RibParser::record_archive(std::string text, const std::string& path) {
  RecordedArchive archive;
  if (std::optional<FileStamp> stamp = stamp_file(archive_file(path))) archive.files.push_back(*stamp);
  archive.declarations_before = declared_;
  archive.search_path_before = archive_path_;
  int64_t errors_kept = 0;
  bool replayable = true;
  // The archive's own parser: the same state as this one, a target that records, and
  // diagnostics that are recorded too (shown when replayed, so each frame that reads the
  // archive gets its errors, as without the cache).
  Diagnostics recorded_diag([&](const Diagnostic& d) {
    if (d.severity == Severity::Error) ++errors_kept;
    archive.events.push_back(RecordedArchive::Event{{}, d});
  });
  CallRecorder recorder([&](CallRecorder::Entry call) {
    if (call.request == "ErrorHandler") replayable = false;  // it changes this parser's diagnostics
    archive.events.push_back(RecordedArchive::Event{std::move(call), std::nullopt});
  });
  RibParser child(recorder, recorded_diag);
  child.declared_ = declared_;
  child.archive_path_ = archive_path_;
  child.include_stack_ = include_stack_;
  child.archive_files_allowed_ = archive_files_allowed_;
  child.archive_cache_ = archive_cache_;
  child.text_limits_ = text_limits_;
  child.recorded_files_ = &archive.files;
  child.inline_archives_ = inline_archives_;
  child.inline_stack_ = inline_stack_;
  child.conditions_ = conditions_;
  child.procedural_path_ = procedural_path_;
  child.procedural_path_set_ = procedural_path_set_;
  child.procedural_folders_ = procedural_folders_;
  child.trust_rib_ = trust_rib_;
  child.run_program_limits_ = run_program_limits_;
  child.parse_text(std::move(text), path);
  // Past the message caps some errors were counted but not recorded: a replay would lose them.
  if (!replayable || errors_kept != recorded_diag.error_count()) return std::nullopt;
  // Conditional RIB and inline archives depend on (or change) this parser's state of the
  // moment ($Frame, the archives defined so far): such an archive is parsed at each read.
  if (child.read_parser_state_ || child.procedural_path_set_ != procedural_path_set_ ||
      child.procedural_path_ != procedural_path_)
    return std::nullopt;
  archive.declarations_after = std::move(child.declared_);
  archive.search_path_after = std::move(child.archive_path_);
  return archive;
}

namespace {

// Keeps the variables conditional RIB can refer to in step with replayed calls, as the parser's
// own handlers of these requests do when it reads them.
class ConditionTracker : public RiTargetDefaults {
 public:
  explicit ConditionTracker(ConditionVariables& conditions) : conditions_(conditions) {}
  void frame_begin(int number, const SourceLoc&) override { conditions_.frame_begin(number); }
  void frame_end(const SourceLoc&) override { conditions_.frame_end(); }
  void world_begin(const SourceLoc&) override { conditions_.world_begin(); }
  void world_end(const SourceLoc&) override { conditions_.world_end(); }
  void attribute_begin(const SourceLoc&) override { conditions_.attribute_begin(); }
  void attribute_end(const SourceLoc&) override { conditions_.attribute_end(); }
  void option(const std::string& category, const ParamList& params, const SourceLoc&) override {
    conditions_.option(category, params);
  }
  void attribute(const std::string& category, const ParamList& params, const SourceLoc&) override {
    conditions_.attribute(category, params);
  }

 private:
  ConditionVariables& conditions_;
};

}  // namespace

void RibParser::replay(const RecordedArchive& archive) {
  ConditionTracker condition_tracker(conditions_);
  for (size_t i = 0; i < archive.events.size(); ++i) {
    const RecordedArchive::Event& e = archive.events[i];
    if (diag_.aborted()) return;
    if (e.diagnostic) {
      const Diagnostic& d = *e.diagnostic;
      if (d.severity == Severity::Error) {
        diag_.error(d.loc, d.request, d.message);
      } else {
        // Warnings once per run, as when the archive is parsed each time with one Diagnostics.
        diag_.warning_once("archive " + d.loc.str() + " " + d.message, d.loc, d.request, d.message);
      }
      continue;
    }
    target_.replayed_request(archive.request_id(i));
    try {
      e.call.call(target_);
      // What conditional RIB can refer to, as the requests' own handlers keep it.
      e.call.call(condition_tracker);
    } catch (const RibError& err) {
      diag_.error(e.call.loc, e.call.request, err.what());
    }
    target_.replayed_request(0);
  }
  declared_ = archive.declarations_after;
  archive_path_ = archive.search_path_after;
}

void RibParser::replay_inline_archive(const std::string& name, const InlineArchive& archive) {
  read_parser_state_ = true;
  const std::uint64_t bytes = archive.body.end - archive.body.begin;
  if (inline_replays_ >= kMaxInlineReplays || inline_replayed_bytes_ + bytes > kMaxInlineReplayedBytes) {
    throw RibError(fmt::format("inline archive \"{}\" not read: this run has read inline archives {} times ({} "
                               "bytes), the limit is {} reads or {} bytes (archives that read each other many "
                               "times over?)",
                               name, inline_replays_, inline_replayed_bytes_, kMaxInlineReplays,
                               kMaxInlineReplayedBytes));
  }
  // Every attempt counts, refused ones too: they are work as well.
  ++inline_replays_;
  inline_replayed_bytes_ += bytes;
  if (std::find(inline_stack_.begin(), inline_stack_.end(), name) != inline_stack_.end()) {
    throw RibError(fmt::format("inline archive \"{}\" (ArchiveBegin at {}) includes itself", name,
                               archive.defined_at.str()));
  }
  if (include_stack_.size() + inline_stack_.size() >= kMaxArchiveDepth) {
    throw RibError(fmt::format("archive \"{}\" is nested deeper than {} levels", name, kMaxArchiveDepth));
  }
  // The lexer shares the body's text: a redefinition of the archive during the replay does
  // not pull it away.
  Lexer lexer(archive.body);
  inline_stack_.push_back(name);
  parse_requests(lexer);
  inline_stack_.pop_back();
}

}  // namespace darc
