// darc: renders RenderMan RIB files. See README.md for the options and exit codes.
#include "app/app_options.h"
#include "app/render_session.h"

#include <cstdio>
#include <exception>
#include <new>

int main(int argc, char** argv) {
  bool exit_now = false;
  int code = 0;
  darc::AppOptions options = darc::parse_command_line(argc, argv, exit_now, code);
  if (exit_now) return code;
  try {
    return darc::run_render_session(options);
  } catch (const std::bad_alloc&) {
    // An allocation the frame memory limit did not foresee failed (ulimit -v, say): say so
    // instead of dying on an uncaught exception. Files are written by rename, so none is partial.
    std::fprintf(stderr, "darc: error: out of memory (an allocation failed); --memory-limit or a smaller scene\n");
    return darc::kExitRenderError;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "darc: error: %s\n", e.what());
    return darc::kExitRenderError;
  }
}
