#include "app/frame_list.h"

#include <charconv>
#include <cstdint>
#include <cstdio>

namespace darc {

namespace {

bool parse_int(std::string_view s, int& out) {
  if (s.empty()) return false;
  auto r = std::from_chars(s.data(), s.data() + s.size(), out);
  return r.ec == std::errc() && r.ptr == s.data() + s.size();
}

std::string pad(int value, int width) {
  // In 64 bits: -INT_MIN does not fit an int (FrameBegin -2147483648 is a valid frame number).
  const std::int64_t wide = value;
  std::string digits = std::to_string(wide < 0 ? -wide : wide);
  if (int(digits.size()) < width) digits.insert(0, size_t(width) - digits.size(), '0');
  return value < 0 ? "-" + digits : digits;
}

}  // namespace

std::optional<FrameList> FrameList::parse(const std::string& text, std::string& error) {
  FrameList list;
  size_t pos = 0;
  while (pos <= text.size()) {
    size_t comma = text.find(',', pos);
    std::string_view item(text.data() + pos, (comma == std::string::npos ? text.size() : comma) - pos);
    Range r{0, 0, 1};
    std::string_view range = item;
    size_t x = item.find('x');
    if (x != std::string_view::npos) {
      range = item.substr(0, x);
      if (!parse_int(item.substr(x + 1), r.step) || r.step < 1) {
        error = "bad step in frame list item \"" + std::string(item) + "\"";
        return std::nullopt;
      }
    }
    size_t dash = range.find('-', 1);  // a leading '-' would be a sign
    bool ok = dash == std::string_view::npos
                  ? parse_int(range, r.first) && (r.last = r.first, true)
                  : parse_int(range.substr(0, dash), r.first) && parse_int(range.substr(dash + 1), r.last);
    if (!ok || r.last < r.first) {
      error = "bad frame list item \"" + std::string(item) + "\" (expected N, A-B or A-BxS)";
      return std::nullopt;
    }
    list.ranges_.push_back(r);
    if (comma == std::string::npos) break;
    pos = comma + 1;
  }
  return list;
}

bool FrameList::contains(int frame) const {
  for (const Range& r : ranges_)
    if (frame >= r.first && frame <= r.last && (std::int64_t(frame) - r.first) % r.step == 0) return true;
  return false;
}

std::string substitute_frame_number(const std::string& name, int frame) {
  size_t hash = name.find('#');
  if (hash != std::string::npos) {
    size_t end = name.find_first_not_of('#', hash);
    if (end == std::string::npos) end = name.size();
    return name.substr(0, hash) + pad(frame, int(end - hash)) + name.substr(end);
  }
  size_t pct = name.find('%');
  if (pct != std::string::npos) {
    size_t i = pct + 1;
    int width = 0;
    while (i < name.size() && name[i] >= '0' && name[i] <= '9') width = width * 10 + (name[i++] - '0');
    if (i < name.size() && name[i] == 'd') return name.substr(0, pct) + pad(frame, width) + name.substr(i + 1);
  }
  return name;
}

bool has_frame_number_pattern(const std::string& name) {
  // Two different frames give two different names exactly when the name holds a pattern.
  return substitute_frame_number(name, 0) != substitute_frame_number(name, 1);
}

}  // namespace darc
