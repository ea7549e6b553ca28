// Which folders a RIB may put on its procedural search path (Option "searchpath" "procedural").
// The folders RunProgram may start programs from are the user's choice, not the scene's: a RIB
// from someone else must not be able to run /usr/bin/anything by naming /usr/bin. So the user's
// folders (--procedural-path and DARC_PROCEDURAL_PATH) are the most a scene gets, and a folder
// the scene names is kept only when it lies inside one of them, checked on canonical paths so
// that ".." and symbolic links cannot lead out. Only --trust-rib ("I trust this file") lets a
// scene widen the path, and then each widening folder is reported.
#pragma once

#include <string>
#include <vector>

namespace darc {

struct RibFolderVerdict {
  enum class Kind {
    Allowed,  // inside one of the user's folders
    Trusted,  // outside them, kept because the user trusts the RIB (--trust-rib)
    Dropped,  // outside them (or missing), not kept
  };
  Kind kind = Kind::Dropped;
  std::string canonical;  // the folder with links resolved; empty when it does not exist
  std::string reason;     // for Dropped and Trusted: where the folder lies against the user's folders
};

// Judges a folder a RIB names (absolute; a relative one is taken from the RIB file beforehand)
// against the user's folders.
RibFolderVerdict judge_rib_folder(const std::string& folder, const std::vector<std::string>& user_folders,
                                  bool trust_rib);

// The sentence that says how a user allows `folder` for procedural programs, for messages.
std::string how_to_allow_procedural_folder(const std::string& folder);

}  // namespace darc
