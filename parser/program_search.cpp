#include "parser/program_search.h"

#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>

#include "parser/path_containment.h"

namespace darc {

namespace {

namespace fs = std::filesystem;

std::string folder_list(const std::vector<std::string>& folders) {
  std::string list;
  for (const std::string& f : folders) list += (list.empty() ? "" : ", ") + f;
  return list;
}

}  // namespace

ProgramSearch find_program(const std::string& name, const std::vector<std::string>& folders) {
  ProgramSearch result;
  if (name.empty()) {
    result.error = "the program name is empty";
    return result;
  }
  const std::vector<fs::path> trusted = canonical_folders(folders);
  if (trusted.empty()) {
    result.error = folders.empty()
                       ? fmt::format("program \"{}\" refused: no folder may hold procedural programs", name)
                       : fmt::format("program \"{}\" refused: none of the procedural folders exists ({})", name,
                                     folder_list(folders));
    return result;
  }
  std::vector<fs::path> candidates;
  if (fs::path(name).is_absolute()) {
    candidates.push_back(name);
  } else {
    for (const fs::path& dir : trusted) candidates.push_back(dir / name);
  }
  std::string refusal;  // the first candidate that exists but may not run, for the message
  for (const fs::path& candidate : candidates) {
    std::error_code ec;
    const fs::path real = fs::canonical(candidate, ec);
    if (ec) continue;  // not there
    const bool inside =
        std::any_of(trusted.begin(), trusted.end(), [&](const fs::path& dir) { return is_within(real, dir); });
    std::string problem;
    if (!inside) {
      problem = fmt::format("program \"{}\" resolves to {}, outside the procedural search path ({}): refused", name,
                            real.string(), folder_list(folders));
    } else if (!fs::is_regular_file(real, ec)) {
      problem = fmt::format("program \"{}\" ({}) is not a file", name, real.string());
    } else if (::access(real.c_str(), X_OK) != 0) {
      problem = fmt::format("program \"{}\" ({}) is not executable", name, real.string());
    } else {
      result.path = real.string();
      return result;
    }
    if (refusal.empty()) refusal = std::move(problem);
  }
  result.error = !refusal.empty() ? refusal
                                  : fmt::format("program \"{}\" is not in the procedural search path ({})", name,
                                                folder_list(folders));
  return result;
}

}  // namespace darc
