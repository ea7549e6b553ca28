// The darc command run as a user runs it, for the end-to-end tests: in a scratch folder of its
// own, with arguments and an environment the test chooses; what it printed, its exit code, and
// the image it wrote.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "support/image_files.h"

namespace darc::test {

namespace fs = std::filesystem;

// A fresh folder under the system temp folder, named for the test and the process, removed at
// scope end.
class ScratchDir {
 public:
  explicit ScratchDir(const std::string& name);
  ~ScratchDir();
  ScratchDir(const ScratchDir&) = delete;
  ScratchDir& operator=(const ScratchDir&) = delete;
  const fs::path& path() const { return path_; }
  fs::path operator/(const std::string& f) const { return path_ / f; }

 private:
  fs::path path_;
};

struct RunResult {
  int exit_code = -1;
  std::string err;  // stderr
  std::string out;  // stdout
};

struct RunOptions {
  bool quiet = true;    // pass --quiet (no progress lines, no "wrote" lines)
  fs::path stdin_file;  // empty: standard input is /dev/null
  // Variables for darc's environment, as the shell writes them ("NAME='value' ..."). The user's
  // DARC_PROCEDURAL_PATH is never passed on: what a test allows, it sets here.
  std::string environment;
};

// Runs `darc ARGS` with the working directory `cwd` and options.environment; captures stdout and
// stderr (into stdout.txt / stderr.txt in `cwd`). stderr is a file, so darc sees no terminal.
RunResult run_darc(const fs::path& cwd, const std::string& args, const RunOptions& options);
inline RunResult run_darc(const fs::path& cwd, const std::string& args) { return run_darc(cwd, args, RunOptions{}); }

// One run of darc on a RIB file and the image it wrote.
struct FileRender {
  RunResult run;
  std::optional<Pixels> image;  // nothing when the image did not read
};

// Runs `darc ARGS 'rib'` in `dir` (so the images its Display lines name land there) and reads
// `image_name` from `dir` (nothing when it is empty). Neither the exit code nor the image is
// checked here: see rendered_cleanly.
FileRender render_file(const ScratchDir& dir, const fs::path& rib, const std::string& args,
                       const std::string& image_name);

// Success when darc exited with 0 and its image read; else says which, with darc's stderr.
::testing::AssertionResult rendered_cleanly(const FileRender& render);

std::string read_text_file(const fs::path& p);
void write_file(const fs::path& p, const std::string& text);

// The names of the files in `dir` (not recursive), sorted.
std::vector<std::string> file_names(const fs::path& dir);

// True when `dir` holds a temporary image (ImageWriter writes "stem.tmp-PID-N.ext", then renames).
bool has_temp_files(const fs::path& dir);

}  // namespace darc::test
