#include "parser/path_containment.h"

namespace darc {

namespace fs = std::filesystem;

bool is_within(const fs::path& path, const fs::path& folder) {
  auto p = path.begin();
  for (auto f = folder.begin(); f != folder.end(); ++f, ++p) {
    // A trailing separator makes an empty last component: "/a/b/" holds what "/a/b" holds.
    if (f->empty() && std::next(f) == folder.end()) return true;
    if (p == path.end() || *p != *f) return false;
  }
  return true;
}

std::optional<fs::path> canonical_folder(const std::string& folder) {
  std::error_code ec;
  fs::path p = fs::canonical(folder, ec);
  if (ec || !fs::is_directory(p, ec)) return std::nullopt;
  return p;
}

std::vector<fs::path> canonical_folders(const std::vector<std::string>& folders) {
  std::vector<fs::path> out;
  for (const std::string& dir : folders)
    if (std::optional<fs::path> p = canonical_folder(dir)) out.push_back(std::move(*p));
  return out;
}

}  // namespace darc
