// Collects warnings and errors from the parser and the scene builder. Messages are formatted
// "file:line:col: error: Request: message" and handed to a sink (by default: printed to stderr)
// as they arrive, as the RI ErrorHandler in effect says (error_handler.h). Counting is exact;
// showing is capped per kind and in total (message_budget.h), and only the shown diagnostics are
// kept, so a file with millions of errors costs counters, not millions of messages. What a
// message quotes of the RIB is bounded (message_excerpt.h).
#pragma once

#include "parser/error_handler.h"
#include "parser/message_budget.h"
#include "parser/source_loc.h"

#include <cstdint>
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

// The errors attributed to one frame: those reported since the previous frame ended, so
// including any before its FrameBegin or WorldBegin. Its image records them.
struct FrameErrors {
  std::int64_t count = 0;
  std::string first;  // the first of them as Diagnostic::str() gives it; "" when count is 0
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

  // The RI ErrorHandler in effect; "print" until set.
  ErrorHandler handler() const { return handler_; }
  // Sets the handler from here on; refused (false) after fix_handler.
  bool set_handler(ErrorHandler handler);
  // Sets the handler for the rest of the run (--strict): later set_handler calls are refused.
  void fix_handler(ErrorHandler handler);
  // An error arrived under "abort": the run stops (the parser reads no further request, and no
  // frame is handed over).
  bool aborted() const { return aborted_; }

  // Every error and warning reported, shown or not.
  std::int64_t error_count() const { return errors_; }
  std::int64_t warning_count() const { return warnings_; }
  // The diagnostics the sink was given (not ignored, within the caps), in order.
  const std::vector<Diagnostic>& all() const { return all_; }
  // The errors since the previous end_frame() (shown or not).
  const FrameErrors& frame_errors() const { return frame_errors_; }
  // A frame has ended (rendered, or not selected): the errors from here on are the next one's.
  void end_frame() { frame_errors_ = {}; }
  // One line per severity that had messages past the caps, e.g. "123456 more errors not shown
  // (limit 20 per kind, 200 in total)"; empty when everything was shown. Print it at the end.
  std::vector<std::string> suppression_summary() const;

 private:
  // `kind` is taken from the message before it is bounded: values cut alike stay apart.
  void emit(Diagnostic d, const std::string& kind, MessageBudget& budget);
  Sink sink_;
  ErrorHandler handler_ = ErrorHandler::Print;
  bool handler_fixed_ = false;
  bool aborted_ = false;
  std::int64_t errors_ = 0;
  std::int64_t warnings_ = 0;
  FrameErrors frame_errors_;
  std::set<std::string> warned_keys_;
  MessageBudget error_budget_, warning_budget_;
  std::vector<Diagnostic> all_;
};

}  // namespace darc
