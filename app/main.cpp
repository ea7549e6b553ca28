// darc: renders RenderMan RIB files. See README.md for the options and exit codes.
#include "app/app_options.h"
#include "app/render_session.h"

#include <cstdio>
#include <exception>

int main(int argc, char** argv) {
  bool exit_now = false;
  int code = 0;
  darc::AppOptions options = darc::parse_command_line(argc, argv, exit_now, code);
  if (exit_now) return code;
  try {
    return darc::run_render_session(options);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "darc: error: %s\n", e.what());
    return darc::kExitRenderError;
  }
}
