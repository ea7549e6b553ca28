#include "parser/diagnostics.h"

#include <cstdio>

namespace darc {

std::string Diagnostic::str() const {
  std::string s = loc.str() + (severity == Severity::Error ? ": error: " : ": warning: ");
  if (!request.empty()) s += request + ": ";
  return s + message;
}

Diagnostics::Diagnostics()
    : sink_([](const Diagnostic& d) { std::fprintf(stderr, "%s\n", d.str().c_str()); }) {}

void Diagnostics::emit(Diagnostic d) {
  if (sink_) sink_(d);
  all_.push_back(std::move(d));
}

void Diagnostics::error(const SourceLoc& loc, const std::string& request, const std::string& message) {
  ++errors_;
  emit({Severity::Error, loc, request, message});
}

void Diagnostics::warning(const SourceLoc& loc, const std::string& request, const std::string& message) {
  ++warnings_;
  emit({Severity::Warning, loc, request, message});
}

void Diagnostics::warning_once(const std::string& key, const SourceLoc& loc, const std::string& request,
                               const std::string& message) {
  if (!warned_keys_.insert(key).second) return;
  warning(loc, request, message);
}

}  // namespace darc
