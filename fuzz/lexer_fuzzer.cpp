// libFuzzer target for the RIB lexer (parser/lexer.h): every input is lexed to its end, through
// both the token path and the numeric fast path of parameter arrays (read_numbers, which the
// request reader calls right after a '['), and the tokens are checked against the lexer's
// promises: numbers finite and within float range, positions 1-based and never going back.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "parser/lexer.h"

namespace {

void check(bool promise) {
  if (!promise) std::abort();  // a broken promise is a finding, like a crash
}

// Tokens of each input passed to describe() (the error-message text): its cases are few, and
// formatting every token would make most of the time per input.
constexpr size_t kTokensDescribed = 32;

bool in_float_range(double v) { return std::isfinite(v) && std::fabs(v) <= std::numeric_limits<float>::max(); }

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  darc::Lexer lexer(std::string(reinterpret_cast<const char*>(data), size),
                    std::make_shared<const std::string>("fuzz.rib"));
  std::vector<float> numbers;
  int last_line = 1;
  // Every token consumes at least one byte, so size + 1 tokens end any input.
  for (size_t tokens = 0; tokens <= size + 1; ++tokens) {
    const darc::Token token = lexer.next();
    check(token.line >= last_line || token.kind == darc::TokenKind::End);
    if (token.kind == darc::TokenKind::End) return 0;
    check(token.line >= 1 && token.column >= 1);
    last_line = token.line;
    if (token.kind == darc::TokenKind::Number) check(in_float_range(token.number));
    if (tokens < kTokensDescribed) (void)darc::describe(token);
    if (token.kind == darc::TokenKind::ArrayBegin) {
      numbers.clear();
      const size_t n = lexer.read_numbers(numbers);
      check(n == numbers.size());
      for (float v : numbers) check(std::isfinite(v));
    }
  }
  check(false);  // the lexer did not reach End
  return 0;
}
