// The condition language of conditional RIB, and the regular expressions of its =~ operator,
// evaluated on their own (parser-level behaviour is in conditional_rib_test.cpp).
#include "parser/condition_expression.h"

#include <gtest/gtest.h>

#include <map>
#include <string>

#include "parser/condition_pattern.h"

namespace darc {
namespace {

// Variables from a map: numbers and strings; names ending in "[]" hold three values.
struct Variables {
  std::map<std::string, ConditionValue, std::less<>> values;
  std::map<std::string, size_t, std::less<>> arrays;

  VariableValue operator()(std::string_view name) const {
    VariableValue v;
    if (auto it = values.find(name); it != values.end()) {
      v.state = VariableValue::State::Scalar;
      v.value = it->second;
    } else if (auto a = arrays.find(name); a != arrays.end()) {
      v.state = VariableValue::State::Array;
      v.array_size = a->second;
    }
    return v;
  }
};

Variables sample_variables() {
  Variables v;
  v.values["Frame"] = 12.0;
  v.values["user:pass"] = std::string("shadow");
  v.values["user:count"] = std::string("3");
  v.values["Option:user:quality"] = 2.0;
  v.arrays["user:color"] = 3;
  return v;
}

ConditionOutcome eval(std::string_view expression) { return evaluate_condition(expression, sample_variables()); }

bool holds(std::string_view expression) {
  const ConditionOutcome o = eval(expression);
  EXPECT_TRUE(o.evaluated()) << expression << ": " << o.failure;
  return o.value;
}

TEST(ConditionExpression, FrameNumberComparisons) {
  EXPECT_TRUE(holds("$Frame == 12"));
  EXPECT_FALSE(holds("$Frame != 12"));
  EXPECT_TRUE(holds("$Frame < 13"));
  EXPECT_TRUE(holds("$Frame <= 12"));
  EXPECT_FALSE(holds("$Frame > 12"));
  EXPECT_TRUE(holds("$Frame >= 12"));
  EXPECT_TRUE(holds("${Frame} == 12"));
}

TEST(ConditionExpression, StringsCompareByByteOrderAndNumericStringsAsNumbers) {
  EXPECT_TRUE(holds("$user:pass == 'shadow'"));
  EXPECT_TRUE(holds("$user:pass == \"shadow\""));
  EXPECT_FALSE(holds("$user:pass == 'beauty'"));
  EXPECT_TRUE(holds("'abc' < 'abd'"));
  EXPECT_TRUE(holds("$user:count == 3")) << "a string that spells a number compares as that number";
  EXPECT_TRUE(holds("$user:count > 2.5"));
}

TEST(ConditionExpression, LogicPrecedenceAndParentheses) {
  EXPECT_TRUE(holds("$Frame == 1 || $Frame == 12"));
  EXPECT_FALSE(holds("$Frame == 12 && $user:pass == 'beauty'"));
  EXPECT_TRUE(holds("!($Frame == 1)"));
  EXPECT_TRUE(holds("1 || 0 && 0")) << "&& binds tighter than ||";
  EXPECT_FALSE(holds("(1 || 0) && 0"));
  EXPECT_TRUE(holds("!0"));
  EXPECT_FALSE(holds("!'x'"));
}

TEST(ConditionExpression, Arithmetic) {
  EXPECT_TRUE(holds("$Frame - 2 * 3 == 6"));
  EXPECT_TRUE(holds("($Frame + 3) / 5 == 3"));
  EXPECT_TRUE(holds("-$Frame < 0"));
}

TEST(ConditionExpression, UndefinedVariablesAreEmptyAndDefinedTellsThem) {
  EXPECT_FALSE(holds("$user:missing == 'shadow'"));
  EXPECT_TRUE(holds("$user:missing == ''"));
  EXPECT_TRUE(holds("$user:missing == 0"));
  EXPECT_FALSE(holds("defined(user:missing)"));
  EXPECT_TRUE(holds("defined(user:pass)"));
  EXPECT_TRUE(holds("defined($user:pass)"));
  EXPECT_TRUE(holds("!defined(user:missing) || $user:missing > 1"));
}

TEST(ConditionExpression, ExplicitOptionLookupAndComputedNames) {
  EXPECT_TRUE(holds("$Option:user:quality == 2"));
  EXPECT_TRUE(holds("$(concat('user:', 'pass')) == 'shadow'"));
  EXPECT_TRUE(holds("concat($user:pass, '_', $Frame) == 'shadow_12'"));
}

TEST(ConditionExpression, PatternMatching) {
  EXPECT_TRUE(holds("$user:pass =~ 'sha'")) << "matches anywhere, as egrep";
  EXPECT_TRUE(holds("$user:pass =~ '^sh.*w$'"));
  EXPECT_FALSE(holds("$user:pass =~ '^beauty|^diffuse'"));
  EXPECT_TRUE(holds("$user:pass =~ '^(beauty|shadow)$'"));
  EXPECT_TRUE(holds("!($user:pass =~ 'beauty')"));
}

TEST(ConditionExpression, WhatCannotBeEvaluatedSaysWhy) {
  for (const char* expression : {"$Frame ==", "$Frame = 12", "foo(1)", "$user:color == 1", "'a' + 1", "1 / 0",
                                 "'shadow", "$user:pass =~ 'sha('", "$Frame == 12 junk", "$user:pass < 3"}) {
    const ConditionOutcome o = eval(expression);
    EXPECT_FALSE(o.evaluated()) << expression;
    EXPECT_FALSE(o.failure.empty()) << expression;
  }
  EXPECT_NE(eval("$user:color == 1").failure.find("3 values"), std::string::npos) << eval("$user:color == 1").failure;
  const std::string bad_pattern = eval("$user:pass =~ 'sha('").failure;
  EXPECT_NE(bad_pattern.find("pattern 'sha(': missing ): sha("), std::string::npos)
      << "the pattern, then RE2's reason quoting the offending part: " << bad_pattern;
}

TEST(ConditionExpression, OperandsThatCannotMatterAreNotEvaluated) {
  EXPECT_FALSE(holds("0 && $user:color == 1"));
  EXPECT_TRUE(holds("1 || 1 / 0"));
}

TEST(ConditionExpression, DeepNestingIsRefusedNotACrash) {
  const std::string deep = std::string(100000, '(') + "1" + std::string(100000, ')');
  const ConditionOutcome o = eval(deep);
  EXPECT_FALSE(o.evaluated());
  EXPECT_NE(o.failure.find("nested"), std::string::npos) << o.failure;
  EXPECT_FALSE(eval(std::string(100000, '!') + "1").evaluated());
}

bool regex_finds(std::string_view pattern, std::string_view subject) {
  std::string error;
  const std::optional<ConditionPattern> re = ConditionPattern::compile(pattern, error);
  EXPECT_TRUE(re.has_value()) << pattern << ": " << error;
  return re && re->search(subject);
}

TEST(ConditionPattern, EgrepSyntax) {
  EXPECT_TRUE(regex_finds("b+", "abbc"));
  EXPECT_FALSE(regex_finds("^b", "abc"));
  EXPECT_TRUE(regex_finds("c$", "abc"));
  EXPECT_FALSE(regex_finds("a$", "abc"));
  EXPECT_TRUE(regex_finds("^a.c$", "abc"));
  EXPECT_TRUE(regex_finds("colou?r", "color"));
  EXPECT_TRUE(regex_finds("[0-9][0-9]*_[a-z]", "pass_12_x"));
  EXPECT_FALSE(regex_finds("[^a-z]", "abc"));
  EXPECT_TRUE(regex_finds("[]x]", "]"));
  EXPECT_TRUE(regex_finds("a\\.b", "a.b"));
  EXPECT_FALSE(regex_finds("a\\.b", "axb"));
  EXPECT_TRUE(regex_finds("(ab|cd)+e", "xcdabe"));
  EXPECT_TRUE(regex_finds("", "anything"));
  EXPECT_TRUE(regex_finds("x*", ""));
}

// What RE2's POSIX syntax adds to the egrep subset the hand-written matcher took before.
TEST(ConditionPattern, BoundedRepetitionPosixClassesAndByteEscapes) {
  EXPECT_TRUE(regex_finds("^a{2}$", "aa"));
  EXPECT_FALSE(regex_finds("^a{2}$", "aaa"));
  EXPECT_TRUE(regex_finds("^_[0-9]{2,4}$", "_123"));
  EXPECT_FALSE(regex_finds("^_[0-9]{2,4}$", "_12345"));
  EXPECT_TRUE(regex_finds("^[[:alpha:]]+[[:digit:]]$", "pass7"));
  EXPECT_FALSE(regex_finds("[[:space:]]", "no_space"));
  EXPECT_TRUE(regex_finds("a\\tb", "a\tb")) << "C escapes stand for their byte";
  EXPECT_FALSE(regex_finds("a\\tb", "atb"));
  EXPECT_TRUE(regex_finds("\\x41\\101", "AA")) << "hexadecimal and octal escapes";
}

// The subject is bytes, not lines or UTF-8 characters, as before.
TEST(ConditionPattern, SubjectIsMatchedByteByByte) {
  EXPECT_TRUE(regex_finds("a.b", "a\nb")) << "'.' is any byte, a newline too";
  EXPECT_FALSE(regex_finds("^b", "a\nb")) << "^ is the start of the subject, not of a line";
  EXPECT_FALSE(regex_finds("a$", "a\nb")) << "$ is the end of the subject, not of a line";
  EXPECT_TRUE(regex_finds("^..$", "\xc3\xa9")) << "a two-byte UTF-8 character is two bytes";
  EXPECT_TRUE(regex_finds("^[^a]$", "\xff")) << "any byte, valid UTF-8 or not";
}

TEST(ConditionPattern, PathologicalPatternsStayLinear) {
  // (a*)*b against many a's takes exponential time with backtracking; here it is one pass.
  const std::string many_a(20000, 'a');
  EXPECT_FALSE(regex_finds("(a*)*b", many_a));
  EXPECT_TRUE(regex_finds("(a|aa)*$", many_a));
  EXPECT_TRUE(regex_finds("a**+?", "b")) << "stacked quantifiers are one quantifier";
  // As deep as the length cap allows: RE2 neither recurses over the nesting nor refuses it.
  const std::string deep = std::string(499, '(') + "a" + std::string(499, ')');
  EXPECT_TRUE(regex_finds(deep, "xay"));
}

TEST(ConditionPattern, UnsupportedOrMalformedPatternsAreRefused) {
  for (const char* pattern : {"(a", "a)", "[a", "*a", "\\1", "[z-a]", "a{1001}", "((a{100}){100}){100}", "\\d", "\\b",
                              "(?i)a", "[a-c-e]", "a\\"}) {
    std::string error;
    EXPECT_FALSE(ConditionPattern::compile(pattern, error).has_value()) << pattern;
    EXPECT_FALSE(error.empty()) << pattern;
  }
  std::string error;
  EXPECT_FALSE(ConditionPattern::compile(std::string(5000, 'a'), error).has_value());
  EXPECT_NE(error.find("longer than"), std::string::npos) << error;
}

}  // namespace
}  // namespace darc
