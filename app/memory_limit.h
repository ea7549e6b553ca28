// How much memory this process may use, from what Linux says: the memory available on the
// machine (/proc/meminfo MemAvailable), the limit of the process's cgroup (cgroup v2
// memory.max, or v1 memory.limit_in_bytes, less what the rest of the group uses: what a Slurm
// job's --mem or a container sets), and the address-space and data rlimits (ulimit -v, -d). darc turns the smallest into
// the frame memory limit that SceneBuilder checks, so that a scene too large for the machine
// fails with a clear error instead of being killed by the kernel's OOM killer.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace darc {

struct MemoryLimit {
  uint64_t bytes = 0;  // what the process may hold in all
  std::string source;  // which limit it is, for the error message
};

// The inputs, as text, so that the rules can be tested on any machine.
struct MemoryLimitInputs {
  std::string meminfo;             // /proc/meminfo
  std::string cgroup_max;          // the cgroup's limit: v2 memory.max ("max" or bytes) or v1
                                   // memory.limit_in_bytes (huge: none); empty: no cgroup
  std::string cgroup_current;      // what the cgroup uses (memory.current / memory.usage_in_bytes)
  uint64_t rlimit_as = 0;          // 0: unlimited
  uint64_t rlimit_data = 0;        // 0: unlimited
  uint64_t process_resident = 0;   // RssAnon now (part of what the cgroup's current counts)
  uint64_t process_virtual = 0;    // VmSize now (what RLIMIT_AS counts)
  uint64_t process_data = 0;       // VmData now (what RLIMIT_DATA counts)
};

// The smallest of the limits, as a total for this process (its current use included);
// nullopt when none can be read.
std::optional<MemoryLimit> memory_limit(const MemoryLimitInputs& in);

// Reads the inputs of this process (Linux /proc and /sys/fs/cgroup).
MemoryLimitInputs this_process_memory_inputs();

// "4G", "512M", "300k", "123456" (bytes) -> bytes; nullopt when malformed. Suffixes are powers of
// 1024, as in Slurm's --mem.
std::optional<uint64_t> parse_byte_size(std::string_view text);

}  // namespace darc
