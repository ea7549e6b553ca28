// How much of a RIB's own text a diagnostic may repeat. Messages quote what they complain about
// (a request name, a string value), and they go to standard error and, for a frame's first error,
// into the image's metadata (darc:first_error), which may travel further than the file did. A
// file read as an archive may not be the RIB it claims to be, so every quoted value is cut to a
// short excerpt, every control byte is written as \xNN (no terminal escape sequence gets
// through), and a whole message has a cap.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace darc {

// The longest quoted value a message keeps whole: two lines of a terminal, so that a long path
// still reads whole, and a token of a file is a line at most; a longer value keeps its first
// kExcerptHeadBytes and last kExcerptTailBytes around "..." (a path's start and its file name).
inline constexpr size_t kMaxQuotedBytes = 160;
inline constexpr size_t kExcerptHeadBytes = 112;
inline constexpr size_t kExcerptTailBytes = 40;
// The longest message: a few lines of a terminal; past it the message ends in "...".
inline constexpr size_t kMaxMessageBytes = 1024;

// `text` with control bytes escaped and, past kMaxQuotedBytes, cut in the middle.
std::string excerpt(std::string_view text);

// `message` with every double-quoted value passed through excerpt(), control bytes outside
// quotes escaped too, and the whole cut at kMaxMessageBytes.
std::string bounded_message(std::string_view message);

}  // namespace darc
