// The regular expressions of conditional RIB's `=~` operator (RI Spec 3.4 RiIfBegin), matched by
// RE2 in its POSIX egrep mode: literals, `.`, bracket expressions with ranges, `^` and POSIX
// classes (`[[:alpha:]]`), `*` `+` `?` and `{m,n}` (m, n <= 1000), `|`, parentheses, `^` and `$`
// anchoring at the start and end of the subject only, `\` before punctuation quoting it; `\n`
// `\t` `\r` `\f` `\v` `\a`, octal `\0..` and hex `\x..` stand for those bytes. Refused: Perl's
// `\d \w \s \b`, `(?...)` groups, back-references, `\` before any other letter, digit or non-ASCII
// byte, and a `-` inside a bracket expression except first or last. Bytes are matched one by one
// (Latin-1: `.` is one byte, also a newline). The pattern matches anywhere in the subject, as
// egrep and Perl's `=~` do.
//
// RE2 runs in time linear in the subject for any pattern, with no recursion over the pattern's
// nesting and memory bounded per pattern, so a RIB file cannot make it hang, overflow the stack
// or exhaust memory (std::regex's backtracking can).
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <string_view>

namespace re2 {
class RE2;
}

namespace darc {

class ConditionPattern {
 public:
  // Compiles `pattern`; nullopt with `error` set (RE2's reason and the offending part) when it is
  // malformed, uses syntax beyond the above, or is too long or too large to compile.
  static std::optional<ConditionPattern> compile(std::string_view pattern, std::string& error);

  // Whether the pattern matches some part of `subject`.
  bool search(std::string_view subject) const;

  ConditionPattern(ConditionPattern&&) noexcept;
  ConditionPattern& operator=(ConditionPattern&&) noexcept;
  ~ConditionPattern();

 private:
  explicit ConditionPattern(std::unique_ptr<const re2::RE2> regex);
  std::unique_ptr<const re2::RE2> regex_;  // never null
};

}  // namespace darc
