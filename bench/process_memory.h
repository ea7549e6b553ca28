// Resident memory of this process, read from /proc/self/status (Linux): the current resident
// set (VmRSS) and its peak so far (VmHWM), for the benchmark's memory figures. Not a measure of
// what a data structure needs (the allocator keeps freed pages, pages are shared): the report
// states it as the growth of the resident set around loading and building a scene.
#pragma once

#include <cstdint>
#include <fstream>
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

}  // namespace darc::bench
