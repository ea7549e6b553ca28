// The condition language of conditional RIB (IfBegin / ElseIf: RI Spec 3.4 RiIfBegin, PRMan's
// "Conditional RIB", Pixie's documentation of the same):
//
//   numbers 3, 1.5, .5e2      strings 'shadow' (or "shadow")
//   $Frame                    the frame number (FrameBegin)
//   $user:pass, ${user:pass}  an attribute of that category and name, else an option of it
//   $Attribute:user:pass      an attribute only;  $Option:user:pass  an option only
//   $(expr)                   the variable whose name is the string value of expr
//   defined(user:pass)        1 when the variable has a value (the `$` is optional)
//   concat(a, b, ...)         the strings joined (numbers formatted as %g would)
//   a =~ 'regex'              1 when the egrep regular expression matches part of a (RE2's
//                             POSIX syntax, parser/condition_pattern.h)
//   == != < <= > >=           numbers numerically, strings by byte order; a string that spells
//                             a number compares as that number with a number
//   + - * /  ! && ||  ( )     arithmetic on numbers, C's logic and precedence
//
// A variable without a value is the empty string (0 as a number). A variable with several
// values, a syntax darc does not know, a type mismatch or a division by zero make the
// expression unevaluable: the outcome says why, and the caller decides what to do (RibParser
// warns and takes the branch).
#pragma once

#include <functional>
#include <string>
#include <string_view>
#include <variant>

namespace darc {

// A value in a condition: a number or a string.
using ConditionValue = std::variant<double, std::string>;

// What a `$name` reference finds.
struct VariableValue {
  enum class State { Undefined, Scalar, Array };
  State state = State::Undefined;
  ConditionValue value;   // Scalar only
  size_t array_size = 0;  // Array only
};

// Looks a variable up by its name without the `$` ("Frame", "user:pass", "Option:user:pass").
using VariableLookup = std::function<VariableValue(std::string_view name)>;

struct ConditionOutcome {
  bool value = false;
  std::string failure;  // why the expression could not be evaluated; empty when it was
  bool evaluated() const { return failure.empty(); }
};

ConditionOutcome evaluate_condition(std::string_view expression, const VariableLookup& lookup);

}  // namespace darc
