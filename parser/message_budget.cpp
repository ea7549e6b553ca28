#include "parser/message_budget.h"

#include <cctype>

namespace darc {

namespace {

bool is_digit(char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; }
bool is_word_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_'; }

// The end of the number starting at `i` (digits, a fraction, an exponent), or `i` when no
// number starts there. A sign or a leading '.' counts only when a digit follows, and a digit
// glued to a word ("Pw2") is part of the word, not a number.
size_t number_end(const std::string& s, size_t i) {
  if (i > 0 && is_word_char(s[i - 1])) return i;
  size_t j = i;
  if (j < s.size() && (s[j] == '-' || s[j] == '+')) ++j;
  const size_t digits_start = j;
  while (j < s.size() && is_digit(s[j])) ++j;
  if (j < s.size() && s[j] == '.') {
    ++j;
    while (j < s.size() && is_digit(s[j])) ++j;
  }
  if (j == digits_start || (j == digits_start + 1 && s[digits_start] == '.')) return i;  // no digit
  if (j < s.size() && (s[j] == 'e' || s[j] == 'E')) {
    size_t k = j + 1;
    if (k < s.size() && (s[k] == '-' || s[k] == '+')) ++k;
    if (k < s.size() && is_digit(s[k])) {
      while (k < s.size() && is_digit(s[k])) ++k;
      j = k;
    }
  }
  return j;
}

}  // namespace

std::string message_kind(const std::string& request, const std::string& message) {
  std::string kind = request + ": ";
  kind.reserve(kind.size() + message.size());
  for (size_t i = 0; i < message.size();) {
    if (message[i] == '"') {
      const size_t close = message.find('"', i + 1);
      kind += "\"\"";
      if (close == std::string::npos) break;  // an unclosed quote: the rest is the value
      i = close + 1;
      continue;
    }
    const size_t end = number_end(message, i);
    if (end > i) {
      kind += '#';
      i = end;
      continue;
    }
    kind += message[i++];
  }
  return kind;
}

bool MessageBudget::admit(const std::string& kind) {
  if (shown_ >= kMaxShownInTotal) {
    ++suppressed_;
    return false;
  }
  int& shown_of_kind = shown_per_kind_[kind];
  if (shown_of_kind >= kMaxShownPerKind) {
    ++suppressed_;
    return false;
  }
  ++shown_of_kind;
  ++shown_;
  return true;
}

}  // namespace darc
