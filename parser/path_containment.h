// Whether one path lies inside a folder, for the rules that keep what a RIB names (programs,
// search-path folders, output files) inside folders the user chose. The rules compare canonical
// paths (symbolic links resolved, "." and ".." collapsed), so that neither ".." nor a link can
// lead out of a folder that a plain string comparison would accept.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace darc {

// `path` is `folder` or lies below it; both must already be canonical (compared component by
// component, so "/a/bc" is not inside "/a/b").
bool is_within(const std::filesystem::path& path, const std::filesystem::path& folder);

// The canonical form of an existing folder; nullopt when it does not exist or is not a folder.
std::optional<std::filesystem::path> canonical_folder(const std::string& folder);

// The canonical forms of the folders of `folders` that exist, in order.
std::vector<std::filesystem::path> canonical_folders(const std::vector<std::string>& folders);

}  // namespace darc
