#include "parser/condition_pattern.h"

#include <fmt/format.h>
#include <re2/re2.h>

#include <utility>

namespace darc {

namespace {

// Longest pattern compiled: conditions compare pass names and object names, a few dozen bytes.
// RE2's max_mem bounds the compiled program, not the parse before it: a megabyte of '(' takes
// 55 MB to parse (measured), and RE2 prints to stderr on such input. The cap bounds both.
constexpr size_t kMaxPatternBytes = 1000;
// RE2's memory budget per pattern (two thirds for the compiled program, the rest for the DFA's
// state cache, which falls back to the linear NFA when full). The largest program a 1000-byte
// pattern can make under RE2's cap of 1000 repetitions (`[a-z]{1000}`: about 1000 instructions)
// fits many times over; a pattern that does not fit is refused as "pattern too large".
constexpr int64_t kMaxPatternMemoryBytes = int64_t(1) << 20;

RE2::Options egrep_options() {
  RE2::Options o;
  o.set_posix_syntax(true);                      // egrep syntax, not Perl's
  o.set_one_line(true);                          // ^ and $ at the ends of the subject only, not at its newlines
  o.set_dot_nl(true);                            // `.` is any byte, a newline too
  o.set_encoding(RE2::Options::EncodingLatin1);  // byte by byte, whatever the RIB file's encoding
  o.set_never_capture(true);                     // only whether it matches is asked
  o.set_log_errors(false);                       // errors are returned to the caller
  o.set_max_mem(kMaxPatternMemoryBytes);
  return o;
}

}  // namespace

ConditionPattern::ConditionPattern(std::unique_ptr<const re2::RE2> regex) : regex_(std::move(regex)) {}
ConditionPattern::ConditionPattern(ConditionPattern&&) noexcept = default;
ConditionPattern& ConditionPattern::operator=(ConditionPattern&&) noexcept = default;
ConditionPattern::~ConditionPattern() = default;

std::optional<ConditionPattern> ConditionPattern::compile(std::string_view pattern, std::string& error) {
  if (pattern.size() > kMaxPatternBytes) {
    error = fmt::format("the pattern is longer than {} bytes", kMaxPatternBytes);
    return std::nullopt;
  }
  auto regex = std::make_unique<const RE2>(re2::StringPiece(pattern.data(), pattern.size()), egrep_options());
  if (!regex->ok()) {
    // RE2's text names the problem and quotes the offending part: "missing ): (a".
    error = regex->error();
    return std::nullopt;
  }
  return ConditionPattern(std::move(regex));
}

bool ConditionPattern::search(std::string_view subject) const {
  return RE2::PartialMatch(re2::StringPiece(subject.data(), subject.size()), *regex_);
}

}  // namespace darc
