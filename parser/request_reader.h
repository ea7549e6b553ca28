// Reads the arguments of one RIB request from the lexer: typed fixed arguments (with the
// bracket-optional and integral-real leniencies real files need) and typed parameter lists.
// Every reader either consumes exactly what it accepts or throws RibSyntaxError without
// consuming the offending token, so the parser can resume at the next request name.
#pragma once

#include <array>
#include <string>
#include <unordered_map>
#include <vector>

#include "parser/diagnostics.h"
#include "parser/lexer.h"
#include "parser/param_list.h"
#include "parser/ri_target.h"

namespace darc {

// A syntax or argument error at a known position (the offending token's).
class RibSyntaxError : public RibError {
 public:
  RibSyntaxError(SourceLoc where, const std::string& message) : RibError(message), loc(std::move(where)) {}
  SourceLoc loc;
};

// Names given a type by Declare. Declarations are global to a parse (not scoped by blocks).
using DeclarationMap = std::unordered_map<std::string, ParamDecl>;

class RequestReader {
 public:
  RequestReader(Lexer& lexer, const DeclarationMap& declared, Diagnostics& diag)
      : lexer_(lexer), declared_(declared), diag_(diag) {}

  // `what` names the argument in messages: "expected <what>, found <token>".
  double number(const char* what);
  // A number that must be integral (reals such as 320.0 are accepted).
  int integer(const char* what);
  std::string string(const char* what);
  // Exactly `N` numbers, either bare or in one bracketed array.
  template <size_t N>
  std::array<double, N> numbers(const char* what) {
    std::array<double, N> out{};
    read_fixed_numbers(out.data(), N, what);
    return out;
  }
  // `count` numbers, either bare or in one bracketed array.
  std::vector<double> fixed_numbers(size_t count, const char* what) {
    std::vector<double> out(count);
    read_fixed_numbers(out.data(), count, what);
    return out;
  }
  // A bracketed array of numbers; a bare number is accepted as a one-element array.
  std::vector<double> number_array(const char* what);
  // True when the next token opens an array.
  bool at_array();
  // A bracketed array of integers; a bare number is accepted as a one-element array.
  std::vector<int> integer_array(const char* what);
  // A bracketed array of strings; a bare string is accepted as a one-element array.
  std::vector<std::string> string_array(const char* what);
  // A light or object handle: an integer (returned without decimals) or a string.
  std::string handle(const char* what);
  // A Basis argument: a name or 16 numbers.
  BasisArg basis(const char* what);
  // The "token" value pairs up to the next request. `request` decides whether undeclared
  // names warn (they do not for Option, Attribute, Display, Hider).
  ParamList param_list(const std::string& request);
  // Every remaining argument up to the next request, flattened (for ignored requests).
  void flatten_rest(std::vector<double>& numbers, std::vector<std::string>& strings);
  // Discards a parameter list after checking its syntax (undeclared names do not warn: their
  // values are not used).
  void skip_param_list(const std::string& request) { (void)read_param_list(request, false); }
  // True when the next token starts a request or ends the input.
  bool at_request_end();
  // Throws when anything but the next request or the end follows.
  void expect_request_end(const char* request);

 private:
  [[noreturn]] void fail_expected(const std::string& what);
  void read_fixed_numbers(double* out, size_t count, const char* what);
  // Reads one value (bare number or string, or a bracketed array) of a parameter.
  void read_values(Param& param);
  ParamList read_param_list(const std::string& request, bool warn_undeclared);
  ParamDecl resolve_declaration(const std::string& request, const Param& param, bool warn_undeclared);
  void check_values(const Param& param) const;
  int to_integer(const Token& token, const std::string& what) const;

  Lexer& lexer_;
  const DeclarationMap& declared_;
  Diagnostics& diag_;
};

}  // namespace darc
