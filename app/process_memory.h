// The process's peak resident memory (Linux: VmHWM in /proc/self/status), for --stats.
#pragma once

#include <cstdint>

namespace darc {

// Bytes; 0 where the system does not say.
uint64_t peak_resident_bytes();

}  // namespace darc
