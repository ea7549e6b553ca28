// The RIB reader: reads ASCII RIB (plain, gzip or standard input), dispatches each request to
// an RiTarget and reports every error and warning with its file:line:column to Diagnostics,
// recovering at the next request so that one run reports all errors. ReadArchive is inlined
// here (the target never sees it): an inline archive of that name (ArchiveBegin/ArchiveEnd,
// inline_archives.h) first, else a file searched in the including file's directory and then
// Option "searchpath" "archive"; so are the procedurals DelayedReadArchive and RunProgram
// (rib_parser_procedural.cpp). Conditional RIB (IfBegin/ElseIf/Else/IfEnd) is evaluated
// here too (condition_expression.h): the target sees the requests of the branches taken only.
// ErrorHandler is applied here, to the Diagnostics, from the next request on
// (error_handler.h); under "abort" parsing stops at the first error.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "parser/archive_cache.h"
#include "parser/condition_variables.h"
#include "parser/conditional_blocks.h"
#include "parser/diagnostics.h"
#include "parser/inline_archives.h"
#include "parser/request_reader.h"
#include "parser/rib_file.h"
#include "parser/ri_target.h"
#include "parser/run_program.h"

namespace darc {

class Lexer;

class RibParser {
 public:
  RibParser(RiTarget& target, Diagnostics& diag) : target_(target), diag_(diag) {}

  // Parses a file ("-" = standard input; "*.gz" = gzip). Returns false when anything failed
  // to be read (the file itself, or any request: see the Diagnostics for what).
  bool parse_file(const std::string& path);
  // Parses RIB text; `name` is the file name used in positions and the base for relative
  // ReadArchive paths.
  bool parse_string(std::string_view text, const std::string& name);

  // Parses RIB text that a program gave as calls (the RI bindings, ri/, pass the requests the
  // parser keeps state for through here: Declare, Option, Attribute, FrameBegin, ReadArchive,
  // procedurals): positions start at `at`, and relative archive names are taken from the working
  // folder. Returns false when anything failed.
  bool parse_request_text(std::string text, const SourceLoc& at);
  // The names given a type by Declare so far.
  const DeclarationMap& declarations() const { return declared_; }

  // The archive search path currently in effect (from Option "searchpath" "archive").
  const std::vector<std::string>& archive_search_path() const { return archive_path_; }

  // Whether ReadArchive and procedurals may read files and start programs (the default). When
  // off, every ReadArchive, DelayedReadArchive and RunProgram is an error, no file is looked up
  // or opened and no program started: for input that must not reach the system (fuzzing).
  void allow_archive_files(bool allowed) { archive_files_allowed_ = allowed; }

  // The most bytes of text one file (an input, an archive, a .gz once decompressed) may give;
  // 0 (the default): no limit. `source` says where the limit comes from, for the message.
  void set_text_limit(std::uint64_t bytes, const std::string& source) {
    text_limits_.max_bytes = bytes;
    text_limits_.max_bytes_source = source;
  }

  // Parse each archive once and replay it from `cache` at later ReadArchives of it (nullptr,
  // the default: every ReadArchive reads and parses its file). The cache must outlive the parser;
  // one cache serves every parser of a run.
  void use_archive_cache(ArchiveCache* cache) { archive_cache_ = cache; }

  // Procedurals (rib_parser_procedural.cpp). The folders the user allows RunProgram to start
  // programs from (--procedural-path, DARC_PROCEDURAL_PATH): the procedural search path until the
  // RIB sets one, "@" in Option "searchpath" "procedural", and the most that option may keep
  // (procedural_folders.h). Relative folders are taken from the current directory.
  void set_procedural_folders(const std::vector<std::string>& folders);
  // --trust-rib: the RIB's procedural search path is kept as it says, even where it leaves the
  // user's folders (each such folder is reported once, as a warning at its Option).
  void set_trust_rib(bool trusted) { trust_rib_ = trusted; }
  // The time and output limits of one RunProgram request (--procedural-timeout).
  void set_run_program_limits(const RunProgramLimits& limits) { run_program_limits_ = limits; }
  // The procedural search path currently in effect: the user's folders until the RIB sets
  // Option "searchpath" "procedural", then what was kept of it.
  const std::vector<std::string>& procedural_search_path() const {
    return procedural_path_set_ ? procedural_path_ : procedural_folders_;
  }

 private:
  // What is being read: one file's text or one inline archive's body. Conditional blocks must
  // close in the text that opened them.
  struct TextScope {
    Lexer& lexer;
    ConditionalBlocks conditionals;
  };

  void parse_text(std::string text, const std::string& name);
  void parse_requests(Lexer& lexer);
  void read_requests(TextScope& scope, RequestReader& args);
  void dispatch(const std::string& request, RequestReader& args, const SourceLoc& loc);
  // A request the table does not have: "not supported" when a RenderMan document has it, else
  // "unknown"; one warning per name, the arguments skipped.
  void dispatch_unimplemented(const std::string& request, RequestReader& args, const SourceLoc& loc);
  void skip_to_next_request(Lexer& lexer);
  void read_archive(RequestReader& args, const SourceLoc& loc);
  // Reads the archive `name` (an inline archive of that name, else a file beside the including
  // file, then on the archive search path) into the request stream; errors (missing file, cycle,
  // depth) are reported at `loc`. ReadArchive and DelayedReadArchive both come here.
  void include_archive(const std::string& name, const SourceLoc& loc);
  void replay_inline_archive(const std::string& name, const InlineArchive& archive);
  void archive_begin(RequestReader& args, const SourceLoc& loc);
  // Procedural, Procedural2 (rib_parser_procedural.cpp).
  void procedural(RequestReader& args, const std::string& request, const SourceLoc& loc);
  // Option "searchpath" "procedural": `folders` (expanded, absolute) narrowed to the user's.
  void set_procedural_search_path(const std::vector<std::string>& folders, const SourceLoc& loc);
  void run_procedural_program(const std::string& program, const std::string& data, double detail, const SourceLoc& loc);
  // Reads a procedural's RIB (`read` calls the parser) in the graphics state of its request.
  void expand_procedural(const std::function<void()>& read, const SourceLoc& loc);
  void declare(RequestReader& args, const SourceLoc& loc);
  void option(RequestReader& args, const SourceLoc& loc);
  void attribute(RequestReader& args, const SourceLoc& loc);
  void frame_begin(RequestReader& args, const SourceLoc& loc);
  void error_handler(RequestReader& args, const SourceLoc& loc);
  // IfBegin, ElseIf, Else, IfEnd. Returns false when `request` is none of them.
  bool conditional(const std::string& request, RequestReader& args, const SourceLoc& loc);
  // The value of a branch's condition; true, with a warning, when it cannot be evaluated.
  bool condition_holds(const std::string& expression, const SourceLoc& loc, const std::string& request);
  // Keeps conditions_ in step with the block requests the target accepted.
  void track_block(const std::string& request);
  std::string resolve_archive(const std::string& name) const;
  // Reads an archive's text (a regular file, within the text limit); a RibError says why not.
  std::string read_archive_text(const std::string& name, const std::string& path) const;
  // ReadArchive through the cache: replays the file's entry, or parses the file into one (or,
  // for an archive whose parse cannot be replayed, parses it straight into the target).
  void include_cached_archive(const std::string& name, const std::string& path, const std::string& canonical);
  // Parses `text` of the archive `path` into a recording; nullopt when the recording could not
  // reproduce the parse (an ErrorHandler inside, or more errors than were shown).
  std::optional<RecordedArchive> record_archive(std::string text, const std::string& path);
  void replay(const RecordedArchive& archive);

  RiTarget& target_;
  Diagnostics& diag_;
  DeclarationMap declared_;
  std::vector<std::string> archive_path_;
  std::vector<std::string> include_stack_;  // files being read, outermost first (canonical paths)
  std::vector<std::string> inline_stack_;   // inline archives being replayed, outermost first
  InlineArchiveStore inline_archives_;
  std::uint64_t inline_replays_ = 0, inline_replayed_bytes_ = 0;  // in this parse, against the caps
  ConditionVariables conditions_;
  TextScope* scope_ = nullptr;  // the innermost text being read
  bool archive_files_allowed_ = true;
  ArchiveCache* archive_cache_ = nullptr;
  RibReadLimits text_limits_;  // for the command line's files; archives are regular files only too
  // While this parser records an archive for the cache: the files the recording depends on.
  std::vector<FileStamp>* recorded_files_ = nullptr;
  // Conditional RIB, inline archives or procedurals were used (the archive cache does not
  // replay such text: it depends on the moment, or starts programs).
  bool read_parser_state_ = false;
  std::vector<std::string> procedural_path_;     // what was kept of Option "searchpath" "procedural"
  bool procedural_path_set_ = false;             // the RIB has set procedural_path_
  std::vector<std::string> procedural_folders_;  // the user's: --procedural-path, DARC_PROCEDURAL_PATH
  bool trust_rib_ = false;                       // --trust-rib
  RunProgramLimits run_program_limits_;
};

}  // namespace darc
