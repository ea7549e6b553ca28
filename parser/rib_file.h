// Reads the whole text of a RIB file: "-" is standard input, a name ending in ".gz" is
// decompressed with zlib. What may be read is bounded, because a RIB names its archives itself
// and a hostile one names whatever it likes: an archive must be a regular file (a device such as
// /dev/zero, a named pipe, a socket or a directory is refused before a byte is read, so nothing
// hangs waiting or reads without end) that gives no more than its size says (the kernel's files
// in /proc and /sys say 0 bytes and may never end), and no text may be larger than a limit (a
// device on the command line, or a small .gz that inflates to gigabytes, stops there with an
// error).
#pragma once

#include <cstdint>
#include <string>

namespace darc {

struct RibReadLimits {
  // Refuse anything but a regular file (ReadArchive and the archive procedurals). The files on
  // the command line are the user's: a pipe there ("darc <(generator)") is read to its end.
  bool regular_files_only = false;
  // The most bytes of text (after decompression) one file may give; 0: no limit.
  std::uint64_t max_bytes = 0;
  // Where max_bytes comes from and how it is changed, for the message ("the memory limit;
  // --memory-limit changes it").
  std::string max_bytes_source;
};

// Reads `path` into `text`. Returns false and sets `error` to why (without the file's name)
// when the file cannot be opened, is refused by `limits`, or fails while it is read.
bool read_rib_text(const std::string& path, std::string& text, std::string& error, const RibReadLimits& limits = {});

}  // namespace darc
