// The RI ErrorHandler ([RIS] "Error handling"): what becomes of an error once it is counted.
// "print" (the default) reports it and goes on; the request with the error is skipped and its
// frame is rendered from the rest. "abort" reports it and stops the run: nothing is written for
// the frame it is in. "ignore" reports nothing. Warnings go to the same handler, as in RI, except
// that "abort" never stops for one. Every error is counted whatever the handler (the exit code and
// the image metadata stay exact).
//
// Scope: the handler is interface state, not graphics state. An ErrorHandler request takes effect
// at the next request and holds for the rest of the run (through FrameEnd and WorldEnd, and into
// later input files) until the next ErrorHandler; it is allowed anywhere, also inside the world
// block. --strict fixes "abort" for the whole run, and ErrorHandler requests are then ignored.
#pragma once

#include <optional>
#include <string_view>

namespace darc {

enum class ErrorHandler { Ignore, Print, Abort };

// "ignore", "print" or "abort"; nullopt for any other name.
std::optional<ErrorHandler> error_handler_named(std::string_view name);
const char* to_string(ErrorHandler handler);

}  // namespace darc
