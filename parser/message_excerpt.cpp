#include "parser/message_excerpt.h"

#include <fmt/format.h>

namespace darc {

namespace {

bool is_control(unsigned char c) { return c < 0x20 || c == 0x7f; }

void append_escaped(std::string& out, std::string_view text) {
  for (const char ch : text) {
    const auto c = static_cast<unsigned char>(ch);
    if (is_control(c)) out += fmt::format("\\x{:02x}", c);
    else out += ch;
  }
}

}  // namespace

std::string excerpt(std::string_view text) {
  std::string out;
  if (text.size() <= kMaxQuotedBytes) {
    append_escaped(out, text);
    return out;
  }
  append_escaped(out, text.substr(0, kExcerptHeadBytes));
  out += "...";
  append_escaped(out, text.substr(text.size() - kExcerptTailBytes));
  return out;
}

std::string bounded_message(std::string_view message) {
  std::string out;
  size_t pos = 0;
  while (pos < message.size()) {
    const size_t open = message.find('"', pos);
    if (open == std::string_view::npos) {
      append_escaped(out, message.substr(pos));
      break;
    }
    append_escaped(out, message.substr(pos, open + 1 - pos));
    const size_t close = message.find('"', open + 1);
    if (close == std::string_view::npos) {
      out += excerpt(message.substr(open + 1));  // an unpaired quote: the rest counts as quoted
      break;
    }
    out += excerpt(message.substr(open + 1, close - open - 1));
    out += '"';
    pos = close + 1;
  }
  if (out.size() > kMaxMessageBytes) {
    out.resize(kMaxMessageBytes);
    out += "...";
  }
  return out;
}

}  // namespace darc
