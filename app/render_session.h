// One run of the darc command: parse every input, render each selected frame as its
// WorldEnd arrives, write the images, the stats JSON, and return the exit code.
#pragma once

#include "app/app_options.h"

namespace darc {

int run_render_session(const AppOptions& options);

}  // namespace darc
