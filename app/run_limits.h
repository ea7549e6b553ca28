// The limits and permissions a run applies, from the darc command's options: the memory the run
// may use (and, from it, the most RIB text one file may give and the memory a frame's geometry
// may take), and what procedurals may do (the user's folders, a RunProgram's time limit, whether
// the RIB is trusted). The command (render_session.cpp) and the RI bindings (ri/) apply the same.
#pragma once

#include "app/app_options.h"
#include "app/memory_limit.h"
#include "core/scene/builder/scene_builder.h"
#include "parser/rib_parser.h"

#include <cstdint>
#include <optional>

namespace darc {

// The memory the whole run may use: --memory-limit, else what Linux allows; nullopt for none.
std::optional<MemoryLimit> run_memory_limit(const AppOptions& o);
// No RIB text (an input, an archive, a .gz once decompressed) may be larger than the memory the
// run may use: it could not be held, and a file that never ends or a gzip bomb stops here.
std::uint64_t text_limit_bytes(const AppOptions& o);
void set_text_limit(const AppOptions& o, RibParser& parser);
// The part of the memory limit a frame's geometry may take (SceneBuilder checks its estimate):
// what the process may hold, less what it holds now and twice the largest input file (the parser
// holds a file's text while its frames are built; a gzip file's text is larger than the file,
// which the factor of two roughly covers).
void set_frame_memory_limit(const AppOptions& o, FrameOverrides& overrides);
// The user's procedural folders (--procedural-path, then DARC_PROCEDURAL_PATH), --trust-rib and
// --procedural-timeout. A folder of the variable that does not exist is reported and left out
// (--procedural-path checks its own as a usage error).
void configure_procedurals(const AppOptions& o, RibParser& parser);

}  // namespace darc
