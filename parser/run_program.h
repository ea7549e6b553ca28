// Runs one RunProgram generator for one request, the RI way (RI Spec 3.2, RiProcRunProgram):
// the request line "detail data\n" goes to the program's standard input, and the RIB it writes
// to its standard output up to the byte '\377' is the answer. darc starts one process per
// request: after the terminator its standard input is closed, and it must exit (status 0) within
// the same time limit. The program gets the environment of darc and its own process group, so
// that a timeout kills whatever it started as well. Nothing here decides which programs may run:
// that is program_search.h.
#pragma once

#include <chrono>
#include <cstddef>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace darc {

// Default wall-clock time for one request, from start to exit: a generator that writes the hair
// of a character takes seconds; one that takes a minute is stuck or wrong (--procedural-timeout).
inline constexpr std::chrono::milliseconds kDefaultProgramTimeLimit{60'000};
// Default cap on the RIB one request may write: far above real generators (the hair of a character
// is about 100 MB of RIB), low enough that a runaway program does not fill memory first.
inline constexpr size_t kDefaultProgramOutputLimit = size_t{1} << 30;

struct RunProgramLimits {
  std::chrono::milliseconds time_limit = kDefaultProgramTimeLimit;
  size_t max_output_bytes = kDefaultProgramOutputLimit;
};

struct ProgramAnswer {
  bool ok = false;
  std::string rib;    // what the program wrote before '\377' (when ok)
  std::string error;  // why the request failed (when not ok): "timed out after 2 s", "exited with status 3", ...
};

// Runs argv[0] (a path, not looked up) with the arguments argv[1...], writes `request` to its
// standard input and reads its answer. Each line the program writes to its standard error is
// given to `stderr_line` (without the line break) as it arrives. Never waits past the time
// limit: the program and its process group are killed then.
ProgramAnswer run_program(const std::vector<std::string>& argv, const std::string& request,
                          const RunProgramLimits& limits, const std::function<void(std::string_view)>& stderr_line);

}  // namespace darc
