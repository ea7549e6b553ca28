#include "app/memory_limit.h"

#include <sys/resource.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cstdio>
#include <fstream>
#include <sstream>

namespace darc {
namespace {

std::string read_text_file(const std::string& path) {
  std::ifstream in(path);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// A "Name:   1234 kB" line of /proc/meminfo or /proc/self/status, in bytes.
std::optional<uint64_t> kib_field(std::string_view text, std::string_view name) {
  size_t pos = 0;
  while (pos < text.size()) {
    size_t end = text.find('\n', pos);
    if (end == std::string_view::npos) end = text.size();
    std::string_view line = text.substr(pos, end - pos);
    pos = end + 1;
    if (line.size() <= name.size() || line.substr(0, name.size()) != name || line[name.size()] != ':') continue;
    line.remove_prefix(name.size() + 1);
    while (!line.empty() && (line.front() == ' ' || line.front() == '\t')) line.remove_prefix(1);
    uint64_t kib = 0;
    auto [p, ec] = std::from_chars(line.data(), line.data() + line.size(), kib);
    if (ec != std::errc()) return std::nullopt;
    return kib * 1024;
  }
  return std::nullopt;
}

std::optional<uint64_t> plain_number(std::string_view text) {
  while (!text.empty() && std::isspace(static_cast<unsigned char>(text.back()))) text.remove_suffix(1);
  uint64_t v = 0;
  auto [p, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (ec != std::errc() || p != text.data() + text.size() || text.empty()) return std::nullopt;
  return v;
}

uint64_t rlimit_bytes(int resource) {
  struct rlimit r{};
  if (getrlimit(resource, &r) != 0 || r.rlim_cur == RLIM_INFINITY) return 0;
  return uint64_t(r.rlim_cur);
}

uint64_t less_or_zero(uint64_t a, uint64_t b) { return a > b ? a - b : 0; }

}  // namespace

std::optional<MemoryLimit> memory_limit(const MemoryLimitInputs& in) {
  std::optional<MemoryLimit> best;
  auto consider = [&](uint64_t bytes, std::string source) {
    if (!best || bytes < best->bytes) best = MemoryLimit{bytes, std::move(source)};
  };
  if (auto available = kib_field(in.meminfo, "MemAvailable"))
    consider(*available + in.process_resident, "the memory available on this machine (MemAvailable)");
  // cgroup v1 writes "no limit" as a huge number (2^63 rounded to pages), v2 as "max".
  constexpr uint64_t kNoCgroupLimit = uint64_t(1) << 60;
  if (auto max = plain_number(in.cgroup_max); max && *max < kNoCgroupLimit) {
    // The group's other processes keep what they hold; this one may grow by what is left.
    const uint64_t others = less_or_zero(plain_number(in.cgroup_current).value_or(0), in.process_resident);
    consider(less_or_zero(*max, others), "the cgroup's memory.max (a job or container limit)");
  }
  if (in.rlimit_as) consider(in.process_resident + less_or_zero(in.rlimit_as, in.process_virtual), "ulimit -v (RLIMIT_AS)");
  if (in.rlimit_data) consider(in.process_resident + less_or_zero(in.rlimit_data, in.process_data), "ulimit -d (RLIMIT_DATA)");
  return best;
}

MemoryLimitInputs this_process_memory_inputs() {
  MemoryLimitInputs in;
  in.meminfo = read_text_file("/proc/meminfo");
  const std::string status = read_text_file("/proc/self/status");
  // Anonymous pages only: the shared libraries' file pages are reclaimable and mostly charged
  // to whoever read them first.
  in.process_resident = kib_field(status, "RssAnon").value_or(kib_field(status, "VmRSS").value_or(0));
  in.process_virtual = kib_field(status, "VmSize").value_or(0);
  in.process_data = kib_field(status, "VmData").value_or(0);
  // The process's memory cgroup, from /proc/self/cgroup: cgroup v2 ("0::/path", files
  // memory.max and memory.current under /sys/fs/cgroup/path) or v1 ("N:memory:/path", files
  // memory.limit_in_bytes and memory.usage_in_bytes under /sys/fs/cgroup/memory/path). A v1
  // memory line wins where both are present (a hybrid hierarchy keeps memory in v1).
  std::istringstream groups(read_text_file("/proc/self/cgroup"));
  for (std::string line; std::getline(groups, line);) {
    const size_t first = line.find(':'), second = line.find(':', first + 1);
    if (first == std::string::npos || second == std::string::npos) continue;
    const std::string controllers = line.substr(first + 1, second - first - 1), path = line.substr(second + 1);
    if (controllers == "memory" || controllers.find("memory,") == 0 || controllers.find(",memory") != std::string::npos) {
      const std::string dir = "/sys/fs/cgroup/memory" + path;
      in.cgroup_max = read_text_file(dir + "/memory.limit_in_bytes");
      in.cgroup_current = read_text_file(dir + "/memory.usage_in_bytes");
      break;
    }
    if (line.rfind("0::", 0) == 0) {
      const std::string dir = "/sys/fs/cgroup" + path;
      in.cgroup_max = read_text_file(dir + "/memory.max");
      in.cgroup_current = read_text_file(dir + "/memory.current");
    }
  }
  in.rlimit_as = rlimit_bytes(RLIMIT_AS);
  in.rlimit_data = rlimit_bytes(RLIMIT_DATA);
  return in;
}

std::optional<uint64_t> parse_byte_size(std::string_view text) {
  if (text.empty()) return std::nullopt;
  uint64_t scale = 1;
  switch (std::tolower(static_cast<unsigned char>(text.back()))) {
    case 'k': scale = uint64_t(1) << 10; break;
    case 'm': scale = uint64_t(1) << 20; break;
    case 'g': scale = uint64_t(1) << 30; break;
    case 't': scale = uint64_t(1) << 40; break;
    default: break;
  }
  if (scale != 1) text.remove_suffix(1);
  double v = 0;
  auto [p, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (ec != std::errc() || p != text.data() + text.size() || !(v >= 0) || v * double(scale) > 1.8e19) return std::nullopt;
  return uint64_t(v * double(scale));
}

}  // namespace darc
