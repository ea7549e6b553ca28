#include "core/scene/builder/display_confinement.h"

#include <fmt/format.h>

#include "parser/path_containment.h"

namespace darc {

namespace fs = std::filesystem;

namespace {

std::string last_component(const fs::path& name) {
  const std::string file = name.filename().string();
  return file == "." || file == ".." ? std::string() : file;
}

}  // namespace

DisplayNameCheck check_display_name(const std::string& name, const fs::path& folder) {
  DisplayNameCheck check;
  const fs::path given(name);
  const fs::path normal = given.lexically_normal();
  if (name.empty()) return check;  // the default name, in the working folder
  if (given.is_absolute()) {
    check.reason = "it is an absolute path";
  } else if (!normal.empty() && *normal.begin() == "..") {
    check.reason = "its \"..\" leads out of the working folder";
  } else if (last_component(normal).empty()) {
    check.reason = "it names a folder, not a file";
  } else {
    std::error_code ec;
    const fs::path parent = fs::weakly_canonical(folder / normal, ec).parent_path();
    if (ec) {
      check.reason = fmt::format("its folder cannot be resolved ({})", ec.message());
    } else if (!is_within(parent, folder)) {
      check.reason = fmt::format("its folder is {} (through a symbolic link), outside the working folder",
                                 parent.string());
    }
  }
  if (check.reason.empty()) return check;
  check.allowed = false;
  check.fallback = last_component(normal);
  return check;
}

}  // namespace darc
