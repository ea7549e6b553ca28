#include "app/frame_count.h"

#include "parser/rib_file.h"

#include <cctype>
#include <charconv>
#include <filesystem>

namespace darc {
namespace {

bool is_word_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_'; }

// Positions just past each whole-word occurrence of `word`.
template <class F>
void for_each_word(std::string_view text, std::string_view word, F&& f) {
  for (size_t at = text.find(word); at != std::string_view::npos; at = text.find(word, at + 1)) {
    const size_t end = at + word.size();
    if ((at > 0 && is_word_char(text[at - 1])) || (end < text.size() && is_word_char(text[end]))) continue;
    f(end);
  }
}

}  // namespace

int count_frames_in_text(std::string_view text, const std::optional<FrameList>& selected) {
  int frames = 0, worlds = 0;
  bool any_frame = false;
  for_each_word(text, "FrameBegin", [&](size_t end) {
    any_frame = true;
    while (end < text.size() && std::isspace(static_cast<unsigned char>(text[end]))) ++end;
    int number = 0;
    auto [p, ec] = std::from_chars(text.data() + end, text.data() + text.size(), number);
    (void)p;
    if (ec != std::errc()) return;
    if (!selected || selected->contains(number)) ++frames;
  });
  if (any_frame) return frames;
  // No FrameBegin: each world block is a frame, numbered from 1 (as SceneBuilder numbers them).
  for_each_word(text, "WorldBegin", [&](size_t) {
    ++worlds;
    if (!selected || selected->contains(worlds)) ++frames;
  });
  return frames;
}

std::optional<int> count_frames(const std::vector<std::string>& inputs, const std::optional<FrameList>& selected,
                                std::uint64_t max_bytes) {
  int total = 0;
  for (const std::string& in : inputs) {
    if (in == "-" || (in.size() >= 3 && in.compare(in.size() - 3, 3, ".gz") == 0)) return std::nullopt;
    // Only regular files are read twice (a pipe read here would be empty for the parser; it is
    // not even opened, which would let its writer go on), and within the parser's limit.
    std::error_code ec;
    if (!std::filesystem::is_regular_file(in, ec)) return std::nullopt;
    RibReadLimits limits;
    limits.regular_files_only = true;
    limits.max_bytes = max_bytes;
    std::string text, error;
    if (!read_rib_text(in, text, error, limits)) return std::nullopt;
    total += count_frames_in_text(text, selected);
  }
  return total;
}

}  // namespace darc
