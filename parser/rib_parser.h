// The RIB reader: reads ASCII RIB (plain, gzip or standard input), dispatches each request to
// an RiTarget and reports every error and warning with its file:line:column to Diagnostics,
// recovering at the next request so that one run reports all errors. ReadArchive is inlined
// here (the target never sees it), searching the including file's directory and then
// Option "searchpath" "archive"; so are the procedurals DelayedReadArchive and RunProgram
// (rib_parser_procedural.cpp). ErrorHandler is applied here, to the Diagnostics, from the
// next request on (error_handler.h); under "abort" parsing stops at the first error.
#pragma once

#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "parser/diagnostics.h"
#include "parser/request_reader.h"
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

  // The archive search path currently in effect (from Option "searchpath" "archive").
  const std::vector<std::string>& archive_search_path() const { return archive_path_; }

  // Whether ReadArchive and procedurals may read files and start programs (the default). When
  // off, every ReadArchive, DelayedReadArchive and RunProgram is an error, no file is looked up
  // or opened and no program started: for input that must not reach the system (fuzzing).
  void allow_archive_files(bool allowed) { archive_files_allowed_ = allowed; }

  // Procedurals (rib_parser_procedural.cpp). The folders RunProgram may start programs from
  // besides those of Option "searchpath" "procedural" (--procedural-path); "@" in that option
  // stands for them.
  // Relative folders are taken from the current directory.
  void set_procedural_folders(const std::vector<std::string>& folders);
  // The time and output limits of one RunProgram request (--procedural-timeout).
  void set_run_program_limits(const RunProgramLimits& limits) { run_program_limits_ = limits; }
  // The procedural search path currently in effect (from Option "searchpath" "procedural").
  const std::vector<std::string>& procedural_search_path() const { return procedural_path_; }

 private:
  void parse_text(std::string text, const std::string& name);
  void parse_requests(Lexer& lexer);
  void dispatch(const std::string& request, RequestReader& args, const SourceLoc& loc);
  void skip_to_next_request(Lexer& lexer);
  void read_archive(RequestReader& args, const SourceLoc& loc);
  // Reads the archive `name` (beside the including file, then on the archive search path) into
  // the request stream; errors (missing file, cycle, depth) are reported at `loc`. ReadArchive
  // and DelayedReadArchive both come here.
  void include_archive(const std::string& name, const SourceLoc& loc);
  // Procedural, Procedural2 (rib_parser_procedural.cpp).
  void procedural(RequestReader& args, const std::string& request, const SourceLoc& loc);
  void run_procedural_program(const std::string& program, const std::string& data, double detail, const SourceLoc& loc);
  // Reads a procedural's RIB (`read` calls the parser) in the graphics state of its request.
  void expand_procedural(const std::function<void()>& read, const SourceLoc& loc);
  void declare(RequestReader& args, const SourceLoc& loc);
  void option(RequestReader& args, const SourceLoc& loc);
  void error_handler(RequestReader& args, const SourceLoc& loc);
  std::string resolve_archive(const std::string& name) const;

  RiTarget& target_;
  Diagnostics& diag_;
  DeclarationMap declared_;
  std::vector<std::string> archive_path_;
  std::vector<std::string> include_stack_;  // files being read, outermost first (canonical paths)
  bool archive_files_allowed_ = true;
  std::vector<std::string> procedural_path_;     // Option "searchpath" "procedural", absolute
  std::vector<std::string> procedural_folders_;  // --procedural-path
  RunProgramLimits run_program_limits_;
};

}  // namespace darc
