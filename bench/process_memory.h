// Memory of this process for the benchmark's figures: the resident set (VmRSS) and its peak
// (VmHWM) from /proc/self/status (Linux), and the bytes the C heap has handed out (glibc's
// mallinfo2). The resident set is what the machine pays, but the allocator keeps freed pages
// (a scene loaded after another reuses them), so the exact per-scene figure is the growth of the
// heap in use; the report gives both.
#pragma once

#include <cstdint>
#include <fstream>
#include <malloc.h>
#include <optional>
#include <sstream>
#include <string>
#include <string_view>

namespace darc::bench {

// The value of a "Field:   1234 kB" line of /proc/<pid>/status text, in bytes; nullopt when the
// field is absent or malformed. `field` is the name without the colon, e.g. "VmHWM".
inline std::optional<uint64_t> status_field_bytes(std::string_view status, std::string_view field) {
  size_t pos = 0;
  while (pos < status.size()) {
    size_t end = status.find('\n', pos);
    if (end == std::string_view::npos) end = status.size();
    std::string_view line = status.substr(pos, end - pos);
    pos = end + 1;
    if (line.size() <= field.size() || line.substr(0, field.size()) != field || line[field.size()] != ':') continue;
    std::istringstream value{std::string(line.substr(field.size() + 1))};
    uint64_t kib = 0;
    std::string unit;
    if (!(value >> kib >> unit) || unit != "kB") return std::nullopt;
    return kib * 1024;
  }
  return std::nullopt;
}

// VmRSS / VmHWM of this process in bytes, 0 where /proc is not available.
inline uint64_t process_status_bytes(std::string_view field) {
  std::ifstream in("/proc/self/status");
  std::ostringstream text;
  text << in.rdbuf();
  return status_field_bytes(text.str(), field).value_or(0);
}
inline uint64_t resident_bytes() { return process_status_bytes("VmRSS"); }
inline uint64_t peak_resident_bytes() { return process_status_bytes("VmHWM"); }

// Bytes of the C heap in use (small blocks plus mmapped large ones), glibc's own count.
inline uint64_t heap_in_use_bytes() {
  struct mallinfo2 info = mallinfo2();
  return uint64_t(info.uordblks) + uint64_t(info.hblkhd);
}

// Returns the heap's free memory to the system (glibc malloc_trim), so that a resident-set
// reading that follows counts less of what the allocator merely keeps.
inline void trim_heap() { malloc_trim(0); }

// Resets VmHWM to the current resident set (Linux: "5" written to /proc/self/clear_refs), so that
// the next peak_resident_bytes() is the peak since now. False when the kernel refuses it; the
// peak then counts from the start of the process.
inline bool reset_peak_resident() {
  std::ofstream out("/proc/self/clear_refs");
  out << "5";
  out.flush();
  return bool(out);
}

}  // namespace darc::bench
