#include "app/run_limits.h"

#include "app/process_memory.h"
#include "core/scene/frame_memory.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>

namespace darc {

namespace fs = std::filesystem;

std::optional<MemoryLimit> run_memory_limit(const AppOptions& o) {
  if (o.memory_limit_bytes) {
    if (*o.memory_limit_bytes == 0) return std::nullopt;  // --memory-limit none
    return MemoryLimit{*o.memory_limit_bytes, "--memory-limit"};
  }
  std::optional<MemoryLimit> system = memory_limit(this_process_memory_inputs());
  if (system) system->source += "; --memory-limit changes it";
  return system;
}

std::uint64_t text_limit_bytes(const AppOptions& o) {
  const std::optional<MemoryLimit> limit = run_memory_limit(o);
  return limit ? limit->bytes : 0;
}

void set_text_limit(const AppOptions& o, RibParser& parser) {
  if (const std::optional<MemoryLimit> limit = run_memory_limit(o))
    parser.set_text_limit(limit->bytes, "the memory limit, from " + limit->source);
}

void set_frame_memory_limit(const AppOptions& o, FrameOverrides& overrides) {
  const std::optional<MemoryLimit> process_limit = run_memory_limit(o);
  if (!process_limit) return;
  const MemoryLimit& limit = *process_limit;
  const MemoryLimitInputs now = this_process_memory_inputs();
  uint64_t text = 0;
  for (const std::string& in : o.inputs) {
    std::error_code ec;
    if (in != "-") text = std::max<uint64_t>(text, fs::file_size(in, ec) * (ec ? 0 : 1));
  }
  const uint64_t held = now.process_resident + 2 * text;
  overrides.memory_limit_bytes = limit.bytes > held ? limit.bytes - held : 1;
  overrides.memory_limit_source = "the limit is " + format_bytes(limit.bytes) + ", from " + limit.source;
}

void configure_procedurals(const AppOptions& o, RibParser& parser) {
  std::vector<std::string> folders = o.procedural_paths;
  for (const std::string& dir : o.procedural_env_paths) {
    std::error_code ec;
    if (fs::is_directory(dir, ec)) folders.push_back(dir);
    else std::fprintf(stderr, "darc: warning: DARC_PROCEDURAL_PATH: \"%s\" is not a folder: ignored\n", dir.c_str());
  }
  parser.set_procedural_folders(folders);
  parser.set_trust_rib(o.trust_rib);
  RunProgramLimits limits;
  limits.time_limit = std::chrono::milliseconds(std::llround(o.procedural_timeout_seconds * 1000));
  parser.set_run_program_limits(limits);
}

}  // namespace darc
