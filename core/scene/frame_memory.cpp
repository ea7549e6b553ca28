#include "core/scene/frame_memory.h"

#include <cstdio>

namespace darc {

std::string format_bytes(uint64_t bytes) {
  const double b = double(bytes);
  char buf[32];
  if (b >= double(uint64_t(1) << 30)) std::snprintf(buf, sizeof buf, "%.1f GB", b / double(uint64_t(1) << 30));
  else if (b >= double(uint64_t(1) << 20)) std::snprintf(buf, sizeof buf, "%.0f MB", b / double(uint64_t(1) << 20));
  else std::snprintf(buf, sizeof buf, "%.0f kB", b / 1024.0);
  return buf;
}

}  // namespace darc
