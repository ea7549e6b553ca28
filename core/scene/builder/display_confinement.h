// Where a RIB's Display name may write. The name comes from the file, and an absolute name or
// one with ".." would let a RIB someone else wrote overwrite images (or anything with an image's
// extension) wherever the user can write. So, unless the user trusts the RIB (--trust-rib) or
// names the output (-o), a Display name must stay inside the working folder: relative, no ".."
// that leads out, and its folder, with symbolic links resolved, inside the working folder. The
// image is written by renaming a temporary file over the name, so a link as the name's last
// component is replaced, never followed.
#pragma once

#include <filesystem>
#include <string>

namespace darc {

struct DisplayNameCheck {
  bool allowed = true;
  std::string reason;    // why not, when refused
  std::string fallback;  // when refused: the name's last component, "" when it has none
};

// Checks `name` (as the Display request gives it, before the frame number is put in) against
// `folder` (canonical).
DisplayNameCheck check_display_name(const std::string& name, const std::filesystem::path& folder);

}  // namespace darc
