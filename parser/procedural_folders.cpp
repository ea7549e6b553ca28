#include "parser/procedural_folders.h"

#include <fmt/format.h>

#include <algorithm>
#include <filesystem>
#include <optional>

#include "parser/path_containment.h"

namespace darc {

namespace fs = std::filesystem;

namespace {

std::string user_folder_list(const std::vector<std::string>& folders) {
  if (folders.empty()) return "none";
  std::string list;
  for (const std::string& f : folders) list += (list.empty() ? "" : ", ") + f;
  return list;
}

}  // namespace

RibFolderVerdict judge_rib_folder(const std::string& folder, const std::vector<std::string>& user_folders,
                                  bool trust_rib) {
  RibFolderVerdict verdict;
  const std::optional<fs::path> real = canonical_folder(folder);
  if (real) verdict.canonical = real->string();
  const std::vector<fs::path> allowed = canonical_folders(user_folders);
  if (real && std::any_of(allowed.begin(), allowed.end(), [&](const fs::path& a) { return is_within(*real, a); })) {
    verdict.kind = RibFolderVerdict::Kind::Allowed;
    return verdict;
  }
  verdict.reason = real ? fmt::format("{} is not inside the folders you allowed ({})", real->string(),
                                      user_folder_list(user_folders))
                        : "it does not exist";
  verdict.kind = trust_rib ? RibFolderVerdict::Kind::Trusted : RibFolderVerdict::Kind::Dropped;
  return verdict;
}

std::string how_to_allow_procedural_folder(const std::string& folder) {
  return fmt::format(
      "allow it with --procedural-path {} or in DARC_PROCEDURAL_PATH, or trust this RIB with --trust-rib "
      "(docs/threat-model.md)",
      folder);
}

}  // namespace darc
