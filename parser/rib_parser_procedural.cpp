// RibParser's procedurals. DelayedReadArchive (and Procedural2 "DelayedReadArchive2") reads its
// archive as ReadArchive does; RunProgram starts a generator from a trusted folder (the user's,
// or those the RIB's search path keeps of them: procedural_folders.h, program_search.h),
// exchanges one request with it (run_program.h) and reads its answer;
// DynamicLoad is skipped with one warning. What a procedural produces is read where its request
// stands, between AttributeBegin and AttributeEnd: PRMan expands a procedural later, in the
// graphics state saved at its request, so nothing it sets reaches the requests after it.
//
// The bound does not cull. darc traces reflections, refractions and shadows, and geometry outside
// the camera's view still shows in them; so a procedural is expanded unless the target declines it
// (SceneBuilder does for a frame that is not rendered), and the bound only gives RunProgram its
// detail: the bound's area in the image, in pixels.
#include <fmt/format.h>

#include <cctype>
#include <cstdio>
#include <filesystem>
#include <memory>

#include "parser/lexer.h"
#include "parser/procedural.h"
#include "parser/procedural_folders.h"
#include "parser/program_search.h"
#include "parser/rib_parser.h"

namespace darc {

namespace {

namespace fs = std::filesystem;

// How deep procedurals and archives may nest: ReadArchive's limit. A generator whose answer
// calls it again with the same data would otherwise start programs without end.
constexpr size_t kMaxProceduralDepth = 64;

// The program string of RunProgram split on white space, as PRMan does (no quoting).
std::vector<std::string> split_words(const std::string& text) {
  std::vector<std::string> words;
  size_t i = 0;
  while (i < text.size()) {
    while (i < text.size() && std::isspace(static_cast<unsigned char>(text[i]))) ++i;
    const size_t begin = i;
    while (i < text.size() && !std::isspace(static_cast<unsigned char>(text[i]))) ++i;
    if (i > begin) words.push_back(text.substr(begin, i - begin));
  }
  return words;
}

}  // namespace

void RibParser::set_procedural_folders(const std::vector<std::string>& folders) {
  procedural_folders_.clear();
  for (const std::string& dir : folders) {
    std::error_code ec;
    const fs::path absolute = fs::absolute(dir, ec);
    procedural_folders_.push_back(ec ? dir : absolute.string());
  }
}

void RibParser::set_procedural_search_path(const std::vector<std::string>& folders, const SourceLoc& loc) {
  std::vector<std::string> kept;
  for (const std::string& dir : folders) {
    const RibFolderVerdict verdict = judge_rib_folder(dir, procedural_folders_, trust_rib_);
    const std::string shown = verdict.canonical.empty() || verdict.canonical == dir
                                  ? fmt::format("\"{}\"", dir)
                                  : fmt::format("\"{}\" ({})", dir, verdict.canonical);
    switch (verdict.kind) {
      case RibFolderVerdict::Kind::Allowed:
        kept.push_back(dir);
        break;
      case RibFolderVerdict::Kind::Trusted:
        diag_.warning_once("trusted procedural folder " + dir, loc, "Option",
                           fmt::format("trusting the procedural folder {} that the RIB chose (--trust-rib): {}; "
                                       "programs in it may run",
                                       shown, verdict.reason));
        kept.push_back(dir);
        break;
      case RibFolderVerdict::Kind::Dropped:
        diag_.warning(loc, "Option",
                      fmt::format("procedural folder {} dropped from the search path: {}; {}", shown, verdict.reason,
                                  how_to_allow_procedural_folder(verdict.canonical.empty() ? dir : verdict.canonical)));
        break;
    }
  }
  procedural_path_ = std::move(kept);
  procedural_path_set_ = true;
}

void RibParser::procedural(RequestReader& args, const std::string& request, const SourceLoc& loc) {
  read_parser_state_ = true;  // an archive holding procedurals is not replayed from the cache
  const ProceduralCall call = read_procedural(args, request);
  if (call.kind == ProceduralKind::DynamicLoad) {
    diag_.warning_once("procedural DynamicLoad", loc, request,
                       "DynamicLoad is not supported: compiled procedurals cannot be loaded; skipped");
    return;
  }
  if (call.kind == ProceduralKind::Unknown) {
    diag_.warning_once("procedural " + call.type, loc, request,
                       fmt::format("unknown procedural \"{}\": skipped", call.type));
    return;
  }
  if (!archive_files_allowed_)
    throw RibError(fmt::format("{} \"{}\" refused: file access is disabled", call.type, call.strings[0]));
  const ProceduralBound seen = target_.procedural_bound(call.bound, loc);
  if (!seen.wanted) return;
  if (call.kind == ProceduralKind::DelayedReadArchive) {
    expand_procedural([&] { include_archive(call.strings[0], loc); }, loc);
    return;
  }
  run_procedural_program(call.strings[0], call.strings[1], seen.raster_area, loc);
}

void RibParser::run_procedural_program(const std::string& program, const std::string& data, double detail,
                                       const SourceLoc& loc) {
  std::vector<std::string> argv = split_words(program);
  if (argv.empty()) throw RibError("RunProgram: the program name is empty");
  const std::string name = argv[0];  // as written, for messages and positions
  if (include_stack_.size() >= kMaxProceduralDepth)
    throw RibError(
        fmt::format("RunProgram \"{}\": procedurals nested deeper than {} levels", name, kMaxProceduralDepth));
  const std::vector<std::string>& folders = procedural_search_path();
  if (folders.empty()) {
    if (!procedural_folders_.empty())
      throw RibError(fmt::format(
          "RunProgram: program \"{}\" refused: the scene's procedural search path kept no folder (see the warnings "
          "at its Option \"searchpath\" \"procedural\")",
          name));
    throw RibError(fmt::format(
        "RunProgram: program \"{}\" refused: no folder is allowed to hold procedural programs; allow the "
        "generator's folder with --procedural-path DIR or in DARC_PROCEDURAL_PATH (docs/threat-model.md)",
        name));
  }
  const ProgramSearch found = find_program(name, folders);
  if (found.path.empty()) throw RibError("RunProgram: " + found.error);
  argv[0] = found.path;

  // RI: one line "detail data" per request.
  const std::string request = fmt::format("{} {}\n", detail, data);
  // The program's diagnostics go to darc's standard error as they come, marked as its own.
  const std::string stderr_prefix = fmt::format("RunProgram \"{}\" (stderr): ", name);
  ProgramAnswer answer = run_program(argv, request, run_program_limits_, [&](std::string_view line) {
    std::fprintf(stderr, "%s%.*s\n", stderr_prefix.c_str(), static_cast<int>(line.size()), line.data());
  });
  if (!answer.ok) throw RibError(fmt::format("RunProgram \"{}\": {}", name, answer.error));

  expand_procedural(
      [&] {
        Lexer lexer(std::move(answer.rib),
                    std::make_shared<const std::string>(fmt::format("RunProgram \"{}\" (output)", name)));
        // Relative names in the answer (a ReadArchive) are taken from the file of the request, as
        // if the answer stood in it.
        const std::string including = include_stack_.empty() ? std::string() : include_stack_.back();
        include_stack_.push_back(including);
        parse_requests(lexer);
        include_stack_.pop_back();
      },
      loc);
}

void RibParser::expand_procedural(const std::function<void()>& read, const SourceLoc& loc) {
  target_.attribute_begin(loc);
  try {
    read();
  } catch (...) {
    target_.attribute_end(loc);
    throw;
  }
  target_.attribute_end(loc);
}

}  // namespace darc
