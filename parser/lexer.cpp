#include "parser/lexer.h"

#include "parser/simple_decimal.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <limits>

namespace darc {

namespace {

// The largest magnitude a RIB number may have: every value ends up in a float somewhere.
constexpr double kMaxNumberMagnitude = std::numeric_limits<float>::max();
// Longest piece of a malformed token quoted in an error message.
constexpr size_t kMaxQuotedChars = 40;

constexpr bool is_space(unsigned char c) {
  return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v';
}
constexpr bool is_binary(unsigned char c) { return c >= 0x80; }
constexpr bool is_control(unsigned char c) { return (c < 0x20 && !is_space(c)) || c == 0x7f; }
constexpr bool is_delimiter(unsigned char c) { return is_space(c) || c == '"' || c == '[' || c == ']' || c == '#'; }
// Bytes that may continue a word or number token, as a table: the scan loops run once per input byte.
constexpr std::array<bool, 256> make_token_byte_table() {
  std::array<bool, 256> table{};
  for (int c = 0; c < 256; ++c) {
    const auto b = static_cast<unsigned char>(c);
    table[static_cast<size_t>(c)] = !is_delimiter(b) && !is_binary(b) && !is_control(b);
  }
  return table;
}
constexpr std::array<bool, 256> kTokenByte = make_token_byte_table();

size_t token_end(std::string_view text, size_t pos) {
  while (pos < text.size() && kTokenByte[static_cast<unsigned char>(text[pos])]) ++pos;
  return pos;
}

bool starts_number(unsigned char c) { return (c >= '0' && c <= '9') || c == '.' || c == '+' || c == '-'; }

std::string quoted_excerpt(std::string_view s) {
  if (s.size() > kMaxQuotedChars) return std::string(s.substr(0, kMaxQuotedChars)) + "...";
  return std::string(s);
}

}  // namespace

std::string describe(const Token& token) {
  switch (token.kind) {
    case TokenKind::Word:
      return fmt::format("request name {}", quoted_excerpt(token.text));
    case TokenKind::String:
      return fmt::format("string \"{}\"", quoted_excerpt(token.text));
    case TokenKind::Number: {
      char buf[64];
      auto r = std::to_chars(buf, buf + sizeof buf, token.number);
      return fmt::format("number {}", std::string_view(buf, static_cast<size_t>(r.ptr - buf)));
    }
    case TokenKind::ArrayBegin:
      return "'['";
    case TokenKind::ArrayEnd:
      return "']'";
    case TokenKind::End:
      return "end of file";
    case TokenKind::Error:
      return fmt::format("invalid token ({})", token.text);
  }
  return "token";
}

std::optional<std::string_view> leading_word(std::string_view text) {
  size_t pos = 0;
  while (pos < text.size()) {
    const unsigned char c = text[pos];
    if (is_space(c)) {
      ++pos;
    } else if (c == '#') {
      while (pos < text.size() && text[pos] != '\n' && text[pos] != '\r') ++pos;
    } else {
      break;
    }
  }
  if (pos == text.size()) return std::nullopt;
  const unsigned char c = text[pos];
  if (!kTokenByte[c] || starts_number(c)) return std::string_view();
  return text.substr(pos, token_end(text, pos) - pos);
}

Lexer::Lexer(std::string text, std::shared_ptr<const std::string> file)
    : storage_(std::make_shared<const std::string>(std::move(text))), text_(*storage_), file_(std::move(file)) {}

Lexer::Lexer(const RibTextSpan& span)
    : storage_(span.text),
      base_(span.begin),
      text_(std::string_view(*span.text).substr(span.begin, span.end - span.begin)),
      file_(span.file),
      line_(span.line),
      column_shift_(span.column - 1) {}

RibTextSpan Lexer::span(const Token& first, size_t end_offset) const {
  RibTextSpan out;
  out.text = storage_;
  out.begin = base_ + first.offset;
  out.end = base_ + std::max(first.offset, std::min(end_offset, text_.size()));
  out.file = file_;
  out.line = first.line;
  out.column = first.column;
  return out;
}

const Token& Lexer::peek() {
  if (!has_peeked_) {
    peeked_ = scan();
    has_peeked_ = true;
  }
  return peeked_;
}

Token Lexer::next() {
  if (has_peeked_) {
    has_peeked_ = false;
    return std::move(peeked_);
  }
  return scan();
}

void Lexer::advance_line_break() {
  if (text_[pos_] == '\r' && pos_ + 1 < text_.size() && text_[pos_ + 1] == '\n') ++pos_;
  ++pos_;
  ++line_;
  line_start_ = pos_;
  column_shift_ = 0;
}

void Lexer::skip_whitespace_and_comments() {
  while (pos_ < text_.size()) {
    const unsigned char c = text_[pos_];
    if (c == '\n' || c == '\r') {
      advance_line_break();
    } else if (is_space(c)) {
      ++pos_;
    } else if (c == '#') {
      // A comment (and a "##" structure comment) runs to the end of the line; its bytes are
      // free text, so the binary check does not apply to them.
      while (pos_ < text_.size() && text_[pos_] != '\n' && text_[pos_] != '\r') ++pos_;
    } else {
      return;
    }
  }
}

Token Lexer::error(Token token, std::string message, bool stop) {
  token.kind = TokenKind::Error;
  token.text = std::move(message);
  if (stop) stopped_ = true;
  return token;
}

Token Lexer::scan() {
  Token token;
  if (stopped_) return token;
  skip_whitespace_and_comments();
  token.line = line_;
  token.column = static_cast<int>(pos_ - line_start_) + 1 + column_shift_;
  token.offset = pos_;
  if (pos_ >= text_.size()) return token;

  const unsigned char c = text_[pos_];
  if (is_binary(c)) return error(std::move(token), "binary RIB is not supported", true);
  if (is_control(c)) {
    ++pos_;
    return error(std::move(token), fmt::format("unexpected control character 0x{:02x}", c), false);
  }
  switch (c) {
    case '[':
      ++pos_;
      token.kind = TokenKind::ArrayBegin;
      return token;
    case ']':
      ++pos_;
      token.kind = TokenKind::ArrayEnd;
      return token;
    case '"':
      return scan_string(std::move(token));
    default:
      break;
  }
  if (starts_number(c)) return scan_number(std::move(token));
  return scan_word(std::move(token));
}

Token Lexer::scan_string(Token token) {
  ++pos_;  // opening quote
  token.kind = TokenKind::String;
  while (pos_ < text_.size()) {
    const char c = text_[pos_];
    if (c == '"') {
      ++pos_;
      return token;
    }
    if (c == '\n' || c == '\r') {
      token.text += c;
      if (c == '\r' && pos_ + 1 < text_.size() && text_[pos_ + 1] == '\n') token.text += '\n';
      advance_line_break();
      continue;
    }
    if (c == '\\' && pos_ + 1 < text_.size()) {
      const char e = text_[pos_ + 1];
      char resolved = 0;
      switch (e) {
        case '"':
          resolved = '"';
          break;
        case '\\':
          resolved = '\\';
          break;
        case 'n':
          resolved = '\n';
          break;
        case 't':
          resolved = '\t';
          break;
        case 'r':
          resolved = '\r';
          break;
        default:
          break;
      }
      if (resolved != 0) {
        token.text += resolved;
        pos_ += 2;
        continue;
      }
      // Unknown escapes stay verbatim: Windows paths such as "C:\temp\x.rib" are common.
    }
    token.text += c;
    ++pos_;
  }
  token.text.clear();
  return error(std::move(token), "unterminated string", true);
}

Token Lexer::scan_number(Token token) {
  const size_t begin = pos_;
  pos_ = token_end(text_, pos_);
  std::string_view spelling(text_.data() + begin, pos_ - begin);
  // from_chars does not take a leading '+', which RIB allows ("+2").
  std::string_view digits = spelling;
  if (!digits.empty() && digits.front() == '+') digits.remove_prefix(1);
  if (!digits.empty() && digits.front() == '+') digits = {};  // "++2" is malformed
  double value = 0;
  auto [ptr, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
  if (ec == std::errc::result_out_of_range) {
    return error(std::move(token), fmt::format("number {} is out of range", quoted_excerpt(spelling)), false);
  }
  if (ec != std::errc() || ptr != digits.data() + digits.size()) {
    return error(std::move(token), fmt::format("malformed number \"{}\"", quoted_excerpt(spelling)), false);
  }
  // from_chars also accepts "inf" and "nan" spellings after a sign ("-nan"); RIB has neither.
  if (!std::isfinite(value)) {
    return error(std::move(token), fmt::format("\"{}\" is not a finite number", quoted_excerpt(spelling)), false);
  }
  if (std::fabs(value) > kMaxNumberMagnitude) {
    return error(std::move(token), fmt::format("number {} is out of range", quoted_excerpt(spelling)), false);
  }
  token.kind = TokenKind::Number;
  token.number = value;
  return token;
}

size_t Lexer::read_numbers(std::vector<float>& out) {
  if (has_peeked_ || stopped_) return 0;
  size_t count = 0;
  for (;;) {
    skip_whitespace_and_comments();
    if (pos_ >= text_.size() || !starts_number(static_cast<unsigned char>(text_[pos_]))) break;
    // from_chars stops at the first byte that is not part of the number; the number is a whole
    // token only if a delimiter follows (else scan_number reports it).
    const char* first = text_.data() + pos_;
    const char* const text_end = text_.data() + text_.size();
    if (*first == '+') ++first;  // from_chars does not take RIB's leading '+'
    if (*first == '+') break;    // "++2": scan_number reports it
    double value = 0;
    const char* ptr = nullptr;
    if (!parse_simple_decimal(first, text_end, value, ptr)) {
      auto result = std::from_chars(first, text_end, value);
      if (result.ec != std::errc()) break;
      ptr = result.ptr;
    }
    if ((ptr != text_end && kTokenByte[static_cast<unsigned char>(*ptr)]) || !std::isfinite(value) ||
        std::fabs(value) > kMaxNumberMagnitude)
      break;
    const size_t end = size_t(ptr - text_.data());
    out.push_back(static_cast<float>(value));
    pos_ = end;
    ++count;
  }
  return count;
}

Token Lexer::scan_word(Token token) {
  const size_t begin = pos_;
  pos_ = token_end(text_, pos_);
  token.kind = TokenKind::Word;
  token.text.assign(text_, begin, pos_ - begin);
  return token;
}

}  // namespace darc
