// Collects warnings and errors from the parser and the scene builder. Messages are formatted
// "file:line:col: error: Request: message" and printed as they arrive (unless quiet); the
// counts let a frame decide whether it may be written (an error fails its frame).
#pragma once

#include "parser/source_loc.h"

#include <functional>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

namespace darc {

enum class Severity { Warning, Error };

struct Diagnostic {
  Severity severity;
  SourceLoc loc;
  std::string request;  // the RI request being processed, may be empty
  std::string message;
  std::string str() const;
};

// Thrown by RiTarget implementations (and the parser) for a scene error in one request; the
// parser catches it, reports it, and resumes at the next request.
class RibError : public std::runtime_error {
 public:
  explicit RibError(const std::string& message) : std::runtime_error(message) {}
};

class Diagnostics {
 public:
  using Sink = std::function<void(const Diagnostic&)>;
  // The default sink prints to stderr.
  Diagnostics();
  explicit Diagnostics(Sink sink) : sink_(std::move(sink)) {}

  void error(const SourceLoc& loc, const std::string& request, const std::string& message);
  void warning(const SourceLoc& loc, const std::string& request, const std::string& message);
  // Warns only the first time `key` is seen (one warning per unknown request / shader name).
  void warning_once(const std::string& key, const SourceLoc& loc, const std::string& request,
                    const std::string& message);

  int error_count() const { return errors_; }
  int warning_count() const { return warnings_; }
  const std::vector<Diagnostic>& all() const { return all_; }

 private:
  void emit(Diagnostic d);
  Sink sink_;
  int errors_ = 0;
  int warnings_ = 0;
  std::set<std::string> warned_keys_;
  std::vector<Diagnostic> all_;
};

}  // namespace darc
