#include "parser/request_reader.h"

#include <fmt/format.h>

#include <cmath>
#include <limits>

#include "parser/standard_declarations.h"

namespace darc {

namespace {

// Requests whose parameter lists carry vendor-specific names all the time: an undeclared name
// there is normal, so its type is inferred without a warning.
bool infers_silently(const std::string& request) {
  return request == "Option" || request == "Attribute" || request == "Display" || request == "Hider";
}

bool is_integral_int(double v) {
  return v == std::floor(v) && v >= std::numeric_limits<int>::min() && v <= std::numeric_limits<int>::max();
}

std::string format_number(double v) { return fmt::format("{}", v); }

}  // namespace

bool RequestReader::at_request_end() {
  const TokenKind kind = lexer_.peek().kind;
  return kind == TokenKind::Word || kind == TokenKind::End;
}

void RequestReader::expect_request_end(const char* request) {
  if (at_request_end()) return;
  const Token& t = lexer_.peek();
  if (t.kind == TokenKind::Error) fail_expected("");
  throw RibSyntaxError(lexer_.loc(t), fmt::format("unexpected {} after the arguments of {}", describe(t), request));
}

void RequestReader::fail_expected(const std::string& what) {
  const Token& t = lexer_.peek();
  if (t.kind == TokenKind::Error) {
    // A lexical error is the better explanation; consume it so it is reported only once.
    Token bad = lexer_.next();
    throw RibSyntaxError(lexer_.loc(bad), bad.text);
  }
  throw RibSyntaxError(lexer_.loc(t), fmt::format("expected {}, found {}", what, describe(t)));
}

int RequestReader::to_integer(const Token& token, const std::string& what) const {
  if (!is_integral_int(token.number)) {
    throw RibSyntaxError(lexer_.loc(token),
                         fmt::format("expected an integer for {}, found {}", what, format_number(token.number)));
  }
  return static_cast<int>(token.number);
}

double RequestReader::number(const char* what) {
  if (lexer_.peek().kind != TokenKind::Number) fail_expected(fmt::format("a number for {}", what));
  return lexer_.next().number;
}

int RequestReader::integer(const char* what) {
  if (lexer_.peek().kind != TokenKind::Number) fail_expected(fmt::format("an integer for {}", what));
  return to_integer(lexer_.next(), what);
}

std::string RequestReader::string(const char* what) {
  if (lexer_.peek().kind != TokenKind::String) fail_expected(fmt::format("a string for {}", what));
  return lexer_.next().text;
}

void RequestReader::read_fixed_numbers(double* out, size_t count, const char* what) {
  const bool bracketed = lexer_.peek().kind == TokenKind::ArrayBegin;
  if (bracketed) lexer_.next();
  for (size_t i = 0; i < count; ++i) {
    if (lexer_.peek().kind != TokenKind::Number)
      fail_expected(fmt::format("{} numbers for {} (got {})", count, what, i));
    out[i] = lexer_.next().number;
  }
  if (!bracketed) return;
  if (lexer_.peek().kind == TokenKind::Number) {
    throw RibSyntaxError(lexer_.loc(lexer_.peek()), fmt::format("too many numbers for {}: expected {}", what, count));
  }
  if (lexer_.peek().kind != TokenKind::ArrayEnd)
    fail_expected(fmt::format("']' after the {} numbers of {}", count, what));
  lexer_.next();
}

std::vector<int> RequestReader::integer_array(const char* what) {
  std::vector<int> values;
  if (lexer_.peek().kind == TokenKind::Number) {
    values.push_back(to_integer(lexer_.next(), what));
    return values;
  }
  if (lexer_.peek().kind != TokenKind::ArrayBegin) fail_expected(fmt::format("an integer array for {}", what));
  lexer_.next();
  while (lexer_.peek().kind != TokenKind::ArrayEnd) {
    if (lexer_.peek().kind != TokenKind::Number) fail_expected(fmt::format("an integer or ']' in {}", what));
    values.push_back(to_integer(lexer_.next(), what));
  }
  lexer_.next();
  return values;
}

std::vector<double> RequestReader::number_array(const char* what) {
  std::vector<double> values;
  if (lexer_.peek().kind == TokenKind::Number) {
    values.push_back(lexer_.next().number);
    return values;
  }
  if (lexer_.peek().kind != TokenKind::ArrayBegin) fail_expected(fmt::format("a number array for {}", what));
  lexer_.next();
  while (lexer_.peek().kind != TokenKind::ArrayEnd) {
    if (lexer_.peek().kind != TokenKind::Number) fail_expected(fmt::format("a number or ']' in {}", what));
    values.push_back(lexer_.next().number);
  }
  lexer_.next();
  return values;
}

bool RequestReader::at_array() { return lexer_.peek().kind == TokenKind::ArrayBegin; }

std::vector<std::string> RequestReader::string_array(const char* what) {
  std::vector<std::string> values;
  if (lexer_.peek().kind == TokenKind::String) {
    values.push_back(lexer_.next().text);
    return values;
  }
  if (lexer_.peek().kind != TokenKind::ArrayBegin) fail_expected(fmt::format("a string array for {}", what));
  lexer_.next();
  while (lexer_.peek().kind != TokenKind::ArrayEnd) {
    if (lexer_.peek().kind != TokenKind::String) fail_expected(fmt::format("a string or ']' in {}", what));
    values.push_back(lexer_.next().text);
  }
  lexer_.next();
  return values;
}

std::string RequestReader::handle(const char* what) {
  const Token& t = lexer_.peek();
  if (t.kind == TokenKind::String) return lexer_.next().text;
  if (t.kind != TokenKind::Number) fail_expected(fmt::format("an integer or string for {}", what));
  return std::to_string(to_integer(lexer_.next(), what));
}

BasisArg RequestReader::basis(const char* what) {
  BasisArg arg;
  if (lexer_.peek().kind == TokenKind::String) {
    arg.name = lexer_.next().text;
    return arg;
  }
  const TokenKind kind = lexer_.peek().kind;
  if (kind != TokenKind::ArrayBegin && kind != TokenKind::Number) {
    fail_expected(fmt::format("a basis name or 16 numbers for {}", what));
  }
  read_fixed_numbers(arg.matrix.data(), arg.matrix.size(), what);
  return arg;
}

void RequestReader::flatten_rest(std::vector<double>& numbers, std::vector<std::string>& strings) {
  while (!at_request_end()) {
    const Token& t = lexer_.peek();
    if (t.kind == TokenKind::Error) fail_expected("");
    if (t.kind == TokenKind::Number) numbers.push_back(t.number);
    if (t.kind == TokenKind::String) strings.push_back(t.text);
    lexer_.next();
  }
}

void RequestReader::read_values(Param& param) {
  const Token& first = lexer_.peek();
  if (first.kind == TokenKind::Number) {
    param.floats.push_back(static_cast<float>(lexer_.next().number));
    return;
  }
  if (first.kind == TokenKind::String) {
    param.strings.push_back(lexer_.next().text);
    return;
  }
  if (first.kind != TokenKind::ArrayBegin) fail_expected(fmt::format("a value for parameter \"{}\"", param.name));
  lexer_.next();
  lexer_.read_numbers(param.floats);  // the bulk of a numeric array, straight into its values
  while (true) {
    const Token& t = lexer_.peek();
    if (t.kind == TokenKind::ArrayEnd) break;
    if (t.kind == TokenKind::Number && param.strings.empty()) {
      param.floats.push_back(static_cast<float>(t.number));
    } else if (t.kind == TokenKind::String && param.floats.empty()) {
      param.strings.push_back(t.text);
    } else if (t.kind == TokenKind::Number || t.kind == TokenKind::String) {
      throw RibSyntaxError(lexer_.loc(t), fmt::format("the array of \"{}\" mixes numbers and strings", param.name));
    } else {
      fail_expected(fmt::format("a value or ']' in the array of \"{}\"", param.name));
    }
    lexer_.next();
  }
  lexer_.next();
}

ParamDecl RequestReader::resolve_declaration(const std::string& request, const Param& param, bool warn_undeclared) {
  if (auto it = declared_.find(param.name); it != declared_.end()) return it->second;
  if (auto standard = standard_declaration(param.name)) return *standard;
  // Undeclared: type it from its values so that vendor options still pass through.
  ParamDecl inferred;
  if (!param.strings.empty()) {
    inferred.type = ParamType::String;
  } else {
    inferred.array_size = std::max<int>(1, static_cast<int>(param.floats.size()));
  }
  if (warn_undeclared) {
    diag_.warning_once(
        "undeclared parameter " + param.name, param.loc, request,
        fmt::format("parameter \"{}\" is not declared: assuming \"{}\"", param.name, to_string(inferred)));
  }
  return inferred;
}

void RequestReader::check_values(const Param& param) const {
  const ParamDecl& d = param.decl;
  if (d.is_string() && !param.floats.empty()) {
    throw RibSyntaxError(param.loc,
                         fmt::format("\"{}\": expected strings for a string parameter, found numbers", param.name));
  }
  if (!d.is_string() && !param.strings.empty()) {
    throw RibSyntaxError(param.loc, fmt::format("\"{}\": expected numbers for a {} parameter, found strings",
                                                param.name, to_string(d.type)));
  }
  if (d.is_string()) return;
  const size_t group = static_cast<size_t>(d.components());
  if (param.floats.size() % group != 0) {
    std::string type = to_string(d.type);
    if (d.array_size != 1) type += fmt::format("[{}]", d.array_size);
    throw RibSyntaxError(param.loc, fmt::format("\"{}\": {} values must come in groups of {}, found {}", param.name,
                                                type, group, param.floats.size()));
  }
  if (d.type == ParamType::Integer) {
    for (float v : param.floats) {
      if (!is_integral_int(v)) {
        throw RibSyntaxError(param.loc, fmt::format("\"{}\": expected integers, found {}", param.name, v));
      }
    }
  }
}

ParamList RequestReader::param_list(const std::string& request) {
  return read_param_list(request, !infers_silently(request));
}

ParamList RequestReader::read_param_list(const std::string& request, bool warn_undeclared) {
  ParamList list;
  while (!at_request_end()) {
    if (lexer_.peek().kind != TokenKind::String) fail_expected("a parameter name (a string)");
    const Token token = lexer_.next();
    Param param;
    param.loc = lexer_.loc(token);
    std::optional<ParamDecl> inline_decl = parse_inline_decl(token.text, param.name);
    read_values(param);
    param.decl = inline_decl ? *inline_decl : resolve_declaration(request, param, warn_undeclared);
    check_values(param);
    list.params.push_back(std::move(param));
  }
  return list;
}

}  // namespace darc
