#include "parser/diagnostics.h"

#include <fmt/format.h>

#include "parser/message_excerpt.h"

#include <cstdio>

namespace darc {

std::string Diagnostic::str() const {
  std::string s = loc.str() + (severity == Severity::Error ? ": error: " : ": warning: ");
  if (!request.empty()) s += request + ": ";
  return s + message;
}

Diagnostics::Diagnostics()
    : sink_([](const Diagnostic& d) { std::fprintf(stderr, "%s\n", d.str().c_str()); }) {}

bool Diagnostics::set_handler(ErrorHandler handler) {
  if (handler_fixed_) return false;
  handler_ = handler;
  return true;
}

void Diagnostics::fix_handler(ErrorHandler handler) {
  handler_ = handler;
  handler_fixed_ = true;
}

void Diagnostics::emit(Diagnostic d, const std::string& kind, MessageBudget& budget) {
  // Ignored messages are not shown, so they take nothing from the caps.
  if (handler_ == ErrorHandler::Ignore) return;
  if (!budget.admit(kind)) return;
  if (sink_) sink_(d);
  all_.push_back(std::move(d));
}

void Diagnostics::error(const SourceLoc& loc, const std::string& request, const std::string& message) {
  ++errors_;
  Diagnostic d{Severity::Error, loc, excerpt(request), bounded_message(message)};
  if (frame_errors_.count++ == 0) frame_errors_.first = d.str();
  emit(std::move(d), message_kind(request, message), error_budget_);
  if (handler_ == ErrorHandler::Abort) aborted_ = true;
}

void Diagnostics::warning(const SourceLoc& loc, const std::string& request, const std::string& message) {
  ++warnings_;
  emit({Severity::Warning, loc, excerpt(request), bounded_message(message)}, message_kind(request, message),
       warning_budget_);
}

void Diagnostics::warning_once(const std::string& key, const SourceLoc& loc, const std::string& request,
                               const std::string& message) {
  if (!warned_keys_.insert(key).second) return;
  warning(loc, request, message);
}

std::vector<std::string> Diagnostics::suppression_summary() const {
  std::vector<std::string> lines;
  auto add = [&](std::int64_t suppressed, const char* singular, const char* plural) {
    if (suppressed == 0) return;
    lines.push_back(fmt::format("{} more {} not shown (limit {} per kind, {} in total)", suppressed,
                                suppressed == 1 ? singular : plural, kMaxShownPerKind, kMaxShownInTotal));
  };
  add(error_budget_.suppressed(), "error", "errors");
  add(warning_budget_.suppressed(), "warning", "warnings");
  return lines;
}

}  // namespace darc
