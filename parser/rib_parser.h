// The RIB reader: reads ASCII RIB (plain, gzip or standard input), dispatches each request to
// an RiTarget and reports every error and warning with its file:line:column to Diagnostics,
// recovering at the next request so that one run reports all errors. ReadArchive is inlined
// here (the target never sees it), searching the including file's directory and then
// Option "searchpath" "archive". ErrorHandler is applied here, to the Diagnostics, from the
// next request on (error_handler.h); under "abort" parsing stops at the first error.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "parser/diagnostics.h"
#include "parser/request_reader.h"
#include "parser/ri_target.h"

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

  // Whether ReadArchive may read files (the default). When off, every ReadArchive is an error
  // and no file is looked up or opened: for input that must not reach the file system (fuzzing).
  void allow_archive_files(bool allowed) { archive_files_allowed_ = allowed; }

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
};

}  // namespace darc
