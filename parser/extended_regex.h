// The regular expressions of conditional RIB's `=~` operator (RI Spec 3.4 RiIfBegin): egrep
// syntax (literals, `.`, bracket classes with ranges and `^`, `*` `+` `?`, `|`, parentheses,
// `^` and `$` anchors, `\` quoting the next byte), matched anywhere in the subject as egrep and
// Perl's `=~` do. Matching simulates the automaton over all threads at once (Thompson / Pike),
// so it takes time linear in the subject for any pattern: a RIB file cannot make it hang or
// overflow the stack, which std::regex's backtracking can.
#pragma once

#include <bitset>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace darc {

class ExtendedRegex {
 public:
  // Compiles `pattern`; nullopt with `error` set when it is malformed or uses syntax beyond the
  // above (bounded repetition `{m,n}`, POSIX classes `[:alpha:]`, back-references).
  static std::optional<ExtendedRegex> compile(std::string_view pattern, std::string& error);

  // Whether the pattern matches some part of `subject`.
  bool search(std::string_view subject) const;

  enum class Op { Byte, Any, Class, Split, Jump, LineBegin, LineEnd, Match };
  struct Instruction {
    Op op = Op::Match;
    unsigned char byte = 0;  // Byte
    int x = 0, y = 0;        // Split: both targets; Jump: x; Class: index into classes_
  };

 private:
  std::vector<Instruction> program_;
  std::vector<std::bitset<256>> classes_;
  friend class RegexCompiler;
};

}  // namespace darc
