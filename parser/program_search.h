// Which program a RunProgram request may start. A scene file must never start arbitrary commands
// on its own: a program is run only when it lies in one of the trusted folders (the procedural
// search path, which procedural_folders.h keeps inside the folders the user allowed unless the
// user trusts the RIB). The rule is checked on canonical paths, so ".." and symbolic links cannot
// lead out of the folders: the program file itself, after every link is resolved, must be inside
// one of them.
#pragma once

#include <string>
#include <vector>

namespace darc {

struct ProgramSearch {
  std::string path;   // the program found (canonical), empty when refused
  std::string error;  // why it was refused, for the message
};

// Looks `name` up in `folders` (in order). A bare name ("grass.py") is looked for in each
// folder; a name with '/' ("tools/grass.py", "/abs/grass.py", "../x") is taken relative to each
// folder, or as is when absolute, and accepted only if it resolves inside one of the folders.
// The file must be a regular file the user may execute. Folders that do not exist are skipped.
ProgramSearch find_program(const std::string& name, const std::vector<std::string>& folders);

}  // namespace darc
