#include "parser/condition_expression.h"

#include <fmt/format.h>

#include <charconv>
#include <cmath>
#include <optional>
#include <utility>

#include "parser/condition_pattern.h"

namespace darc {

namespace {

// Deepest nesting of parentheses and unary operators: the evaluator recurses once per level,
// and a hostile RIB string of a million '(' must not overflow the stack.
constexpr int kMaxDepth = 64;

class Unevaluable {
 public:
  explicit Unevaluable(std::string m) : message(std::move(m)) {}
  std::string message;
};

bool is_name_start(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_'; }
bool is_name_char(char c) { return is_name_start(c) || (c >= '0' && c <= '9') || c == ':' || c == '.'; }

std::string to_text(const ConditionValue& v) {
  if (const double* d = std::get_if<double>(&v)) return fmt::format("{}", *d);
  return std::get<std::string>(v);
}

// The number a value stands for: itself, or a string that spells one in full ("" is 0, the
// value of an undefined variable).
std::optional<double> to_number(const ConditionValue& v) {
  if (const double* d = std::get_if<double>(&v)) return *d;
  const std::string& s = std::get<std::string>(v);
  if (s.empty()) return 0.0;
  double out = 0;
  const char* first = s.data();
  if (*first == '+') ++first;
  auto [ptr, ec] = std::from_chars(first, s.data() + s.size(), out);
  if (ec != std::errc() || ptr != s.data() + s.size() || !std::isfinite(out)) return std::nullopt;
  return out;
}

bool truth(const ConditionValue& v) {
  if (const double* d = std::get_if<double>(&v)) return *d != 0;
  return !std::get<std::string>(v).empty();
}

std::string describe_value(const ConditionValue& v) {
  if (std::holds_alternative<double>(v)) return to_text(v);
  return fmt::format("'{}'", std::get<std::string>(v));
}

// A recursive-descent parser that evaluates as it reads. Operands that C would not evaluate
// (the right of `0 && x`) are still parsed, with `live` false: their values are not looked at,
// so they cannot make the expression unevaluable.
class ConditionEvaluator {
 public:
  ConditionEvaluator(std::string_view text, const VariableLookup& lookup) : text_(text), lookup_(lookup) {}

  bool run() {
    const ConditionValue v = logical_or(true, 0);
    skip_space();
    if (pos_ < text_.size()) fail_syntax("unexpected text");
    return truth(v);
  }

 private:
  using Value = ConditionValue;

  [[noreturn]] void fail_syntax(const std::string& what) const {
    std::string_view rest = text_.substr(std::min(pos_, text_.size()), 20);
    throw Unevaluable(rest.empty() ? fmt::format("{} at the end", what) : fmt::format("{} at \"{}\"", what, rest));
  }
  [[noreturn]] static void fail(const std::string& why) { throw Unevaluable(why); }

  void skip_space() {
    while (pos_ < text_.size() &&
           (text_[pos_] == ' ' || text_[pos_] == '\t' || text_[pos_] == '\n' || text_[pos_] == '\r'))
      ++pos_;
  }
  // Consumes `op` when it comes next (after spaces).
  bool take(std::string_view op) {
    skip_space();
    if (text_.substr(pos_, op.size()) != op) return false;
    pos_ += op.size();
    return true;
  }
  void expect(std::string_view op) {
    if (!take(op)) fail_syntax(fmt::format("expected '{}'", op));
  }
  void enter(int depth) const {
    if (depth > kMaxDepth) fail(fmt::format("the expression is nested deeper than {} levels", kMaxDepth));
  }

  Value logical_or(bool live, int depth) {
    Value left = logical_and(live, depth);
    while (take("||")) {
      const bool decided = live && truth(left);
      const Value right = logical_and(live && !decided, depth);
      left = (decided || (live && truth(right))) ? 1.0 : 0.0;
    }
    return left;
  }

  Value logical_and(bool live, int depth) {
    Value left = comparison(live, depth);
    while (take("&&")) {
      const bool decided = live && !truth(left);
      const Value right = comparison(live && !decided, depth);
      left = (!decided && live && truth(right)) ? 1.0 : 0.0;
    }
    return left;
  }

  enum class Compare { Equal, NotEqual, Less, LessEqual, Greater, GreaterEqual, Match };

  std::optional<Compare> comparison_operator() {
    // Two-byte operators first, so that "<=" is not read as "<".
    if (take("==")) return Compare::Equal;
    if (take("!=")) return Compare::NotEqual;
    if (take("=~")) return Compare::Match;
    if (take("<=")) return Compare::LessEqual;
    if (take(">=")) return Compare::GreaterEqual;
    if (take("<")) return Compare::Less;
    if (take(">")) return Compare::Greater;
    return std::nullopt;
  }

  Value comparison(bool live, int depth) {
    Value left = sum(live, depth);
    while (const std::optional<Compare> op = comparison_operator()) {
      const Value right = sum(live, depth);
      left = live && compare(*op, left, right) ? 1.0 : 0.0;
    }
    return left;
  }

  static bool compare(Compare op, const Value& a, const Value& b) {
    if (op == Compare::Match) {
      std::string error;
      const std::optional<ConditionPattern> re = ConditionPattern::compile(to_text(b), error);
      if (!re) fail(fmt::format("pattern {}: {}", describe_value(b), error));
      return re->search(to_text(a));
    }
    int order = 0;
    if (std::holds_alternative<std::string>(a) && std::holds_alternative<std::string>(b)) {
      const int c = std::get<std::string>(a).compare(std::get<std::string>(b));
      order = c < 0 ? -1 : (c > 0 ? 1 : 0);
    } else {
      const std::optional<double> x = to_number(a), y = to_number(b);
      if (!x || !y) fail(fmt::format("cannot compare {} with {}", describe_value(a), describe_value(b)));
      order = *x < *y ? -1 : (*x > *y ? 1 : 0);
    }
    switch (op) {
      case Compare::Equal:
        return order == 0;
      case Compare::NotEqual:
        return order != 0;
      case Compare::Less:
        return order < 0;
      case Compare::LessEqual:
        return order <= 0;
      case Compare::Greater:
        return order > 0;
      case Compare::GreaterEqual:
        return order >= 0;
      case Compare::Match:
        break;
    }
    return false;
  }

  static double number_operand(const Value& v, char op) {
    const std::optional<double> x = to_number(v);
    if (!x) fail(fmt::format("'{}' needs numbers, found {}", op, describe_value(v)));
    return *x;
  }

  Value sum(bool live, int depth) {
    Value left = product(live, depth);
    while (true) {
      char op = 0;
      if (take("+"))
        op = '+';
      else if (take("-"))
        op = '-';
      else
        return left;
      const Value right = product(live, depth);
      if (!live) continue;
      const double x = number_operand(left, op), y = number_operand(right, op);
      left = op == '+' ? x + y : x - y;
    }
  }

  Value product(bool live, int depth) {
    Value left = unary(live, depth);
    while (true) {
      char op = 0;
      if (take("*"))
        op = '*';
      else if (take("/"))
        op = '/';
      else
        return left;
      const Value right = unary(live, depth);
      if (!live) continue;
      const double x = number_operand(left, op), y = number_operand(right, op);
      if (op == '/' && y == 0) fail("division by zero");
      left = op == '*' ? x * y : x / y;
    }
  }

  Value unary(bool live, int depth) {
    enter(depth);
    skip_space();
    // "!=" never starts an operand, so a '!' here is logical not.
    if (take("!")) {
      const Value v = unary(live, depth + 1);
      return live && !truth(v) ? 1.0 : 0.0;
    }
    if (take("-")) {
      const Value v = unary(live, depth + 1);
      return live ? Value(-number_operand(v, '-')) : Value(0.0);
    }
    if (take("+")) {
      const Value v = unary(live, depth + 1);
      return live ? Value(number_operand(v, '+')) : Value(0.0);
    }
    return primary(live, depth);
  }

  Value primary(bool live, int depth) {
    skip_space();
    if (pos_ >= text_.size()) fail_syntax("expected a value");
    const char c = text_[pos_];
    if (take("(")) {
      Value v = logical_or(live, depth + 1);
      expect(")");
      return v;
    }
    if (c == '\'' || c == '"') return quoted_string();
    if ((c >= '0' && c <= '9') || c == '.') return number();
    if (c == '$') return variable(live, depth);
    if (is_name_start(c)) return function(live, depth);
    fail_syntax("expected a value");
  }

  Value quoted_string() {
    const char quote = text_[pos_++];
    const size_t end = text_.find(quote, pos_);
    if (end == std::string_view::npos) fail_syntax("unterminated string");
    std::string s(text_.substr(pos_, end - pos_));
    pos_ = end + 1;
    return s;
  }

  Value number() {
    double v = 0;
    const char* first = text_.data() + pos_;
    auto [ptr, ec] = std::from_chars(first, text_.data() + text_.size(), v);
    if (ec != std::errc() || !std::isfinite(v)) fail_syntax("malformed number");
    pos_ += size_t(ptr - first);
    return v;
  }

  std::string name() {
    skip_space();
    const size_t begin = pos_;
    while (pos_ < text_.size() && is_name_char(text_[pos_])) ++pos_;
    if (pos_ == begin) fail_syntax("expected a variable name");
    return std::string(text_.substr(begin, pos_ - begin));
  }

  Value variable(bool live, int depth) {
    ++pos_;  // '$'
    std::string var;
    if (take("{")) {
      var = name();
      expect("}");
    } else if (take("(")) {
      const Value v = logical_or(live, depth + 1);
      expect(")");
      var = to_text(v);
    } else {
      var = name();
    }
    if (!live) return 0.0;
    const VariableValue found = lookup_(var);
    switch (found.state) {
      case VariableValue::State::Undefined:
        return std::string();
      case VariableValue::State::Scalar:
        return found.value;
      case VariableValue::State::Array:
        fail(fmt::format("${} has {} values (only single values can be compared)", var, found.array_size));
    }
    return std::string();
  }

  Value function(bool live, int depth) {
    const std::string word = name();
    if (word == "defined") {
      expect("(");
      take("$");
      const std::string var = name();
      expect(")");
      return live && lookup_(var).state != VariableValue::State::Undefined ? 1.0 : 0.0;
    }
    if (word == "concat") {
      expect("(");
      std::string joined;
      do {
        joined += to_text(logical_or(live, depth + 1));
      } while (take(","));
      expect(")");
      return joined;
    }
    fail(fmt::format("unknown name '{}' (variables start with '$')", word));
  }

  std::string_view text_;
  size_t pos_ = 0;
  const VariableLookup& lookup_;
};

}  // namespace

ConditionOutcome evaluate_condition(std::string_view expression, const VariableLookup& lookup) {
  ConditionOutcome out;
  try {
    out.value = ConditionEvaluator(expression, lookup).run();
  } catch (const Unevaluable& e) {
    out.failure = e.message;
  }
  return out;
}

}  // namespace darc
