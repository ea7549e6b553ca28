// The RIB lexer: turns ASCII RIB text (held whole in memory) into tokens with 1-based line and
// column positions. Lexical errors (malformed or out-of-range numbers, unterminated strings,
// stray control characters, binary RIB) come out as Error tokens so the parser can report them
// with their position and recover; after a binary byte or an unterminated string the lexer
// only returns End, because nothing after that point can be read reliably.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "parser/source_loc.h"

namespace darc {

enum class TokenKind { Word, String, Number, ArrayBegin, ArrayEnd, End, Error };

struct Token {
  TokenKind kind = TokenKind::End;
  std::string text;   // Word: the request name; String: contents with escapes resolved; Error: the message
  double number = 0;  // Number only; always finite and within float range
  int line = 0;       // 1-based
  int column = 0;     // 1-based, in bytes
  size_t offset = 0;  // of its first byte, in the text the lexer reads
};

// A piece of RIB text to be read again later with its original positions (an inline archive's
// body): it shares the text it was cut from, so replaying it copies nothing.
struct RibTextSpan {
  std::shared_ptr<const std::string> text;
  size_t begin = 0, end = 0;  // byte range in *text
  std::shared_ptr<const std::string> file;
  int line = 1, column = 1;  // position of the byte at `begin`
};

// "number 3.5", "string \"abc\"", "'['", "end of file", "request name Foo": for error messages.
std::string describe(const Token& token);

// The first token of `text` when it is a word (where a request name stands), without tokenizing
// the rest: "" when the first token is something else (a number, a string, a bracket, a binary
// or control byte); nullopt when the text holds nothing but white space and comments.
std::optional<std::string_view> leading_word(std::string_view text);

class Lexer {
 public:
  // `file` names the text in positions (shared by every SourceLoc made from this lexer).
  Lexer(std::string text, std::shared_ptr<const std::string> file);
  // Reads a span cut from another text; positions are those of the original.
  explicit Lexer(const RibTextSpan& span);

  // The next token without consuming it.
  const Token& peek();
  // Consumes and returns the next token.
  Token next();
  SourceLoc loc(const Token& token) const { return SourceLoc{file_, token.line, token.column}; }
  // The numeric fast path of parameter arrays: appends the well-formed numbers that follow
  // directly to `out` (as floats), without making tokens, and stops before the first thing that
  // is not one (']', a string, a malformed number: the token path then reads it and reports any
  // error at its position). Returns how many it appended. Call only with no token peeked.
  size_t read_numbers(std::vector<float>& out);
  const std::shared_ptr<const std::string>& file() const { return file_; }
  // The text from `first`'s first byte up to the byte at `end_offset` (a Token::offset of this
  // lexer), as a span that keeps `first`'s position.
  RibTextSpan span(const Token& first, size_t end_offset) const;

 private:
  Token scan();
  void skip_whitespace_and_comments();
  void advance_line_break();  // at '\r' or '\n': consumes one line break (CRLF counts once)
  Token scan_string(Token token);
  Token scan_number(Token token);
  Token scan_word(Token token);
  Token error(Token token, std::string message, bool stop);

  std::shared_ptr<const std::string> storage_;  // owns the bytes text_ views
  size_t base_ = 0;                              // offset of text_ in *storage_
  std::string_view text_;
  std::shared_ptr<const std::string> file_;
  size_t pos_ = 0;
  size_t line_start_ = 0;  // offset of the first byte of the current line
  int line_ = 1;
  int column_shift_ = 0;  // added to columns on the first line of a span that starts mid-line
  bool stopped_ = false;  // set after an unrecoverable error: only End follows
  bool has_peeked_ = false;
  Token peeked_;
};

}  // namespace darc
