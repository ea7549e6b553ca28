#include "support/darc_command.h"

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <iterator>

namespace darc::test {

ScratchDir::ScratchDir(const std::string& name) {
  path_ = fs::temp_directory_path() / ("darc-test-" + name + "-" + std::to_string(::getpid()));
  fs::remove_all(path_);
  fs::create_directories(path_);
}

ScratchDir::~ScratchDir() {
  std::error_code ec;
  fs::remove_all(path_, ec);
}

RunResult run_darc(const fs::path& cwd, const std::string& args, const RunOptions& options) {
  const fs::path outfile = cwd / "stdout.txt", errfile = cwd / "stderr.txt";
  const std::string input = options.stdin_file.empty() ? std::string("/dev/null") : options.stdin_file.string();
  std::string cmd = "cd '" + cwd.string() + "' && env -u DARC_PROCEDURAL_PATH " + options.environment + " '" +
                    std::string(DARC_BINARY) + "' " + (options.quiet ? "--quiet " : "") + args + " < '" + input +
                    "' > '" + outfile.string() + "' 2> '" + errfile.string() + "'";
  int status = std::system(cmd.c_str());
  RunResult r;
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.out = read_text_file(outfile);
  r.err = read_text_file(errfile);
  return r;
}

FileRender render_file(const ScratchDir& dir, const fs::path& rib, const std::string& args,
                       const std::string& image_name) {
  FileRender render;
  render.run = run_darc(dir.path(), args + " '" + rib.string() + "'");
  Pixels image;
  if (!image_name.empty() && read_image(dir / image_name, image)) render.image = std::move(image);
  return render;
}

::testing::AssertionResult rendered_cleanly(const FileRender& render) {
  if (render.run.exit_code != 0)
    return ::testing::AssertionFailure() << "darc exited with " << render.run.exit_code << ":\n" << render.run.err;
  if (!render.image) return ::testing::AssertionFailure() << "its image did not read:\n" << render.run.err;
  return ::testing::AssertionSuccess();
}

std::string read_text_file(const fs::path& p) {
  std::ifstream f(p, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>());
}

void write_file(const fs::path& p, const std::string& text) {
  std::ofstream f(p, std::ios::binary);
  f << text;
}

std::vector<std::string> file_names(const fs::path& dir) {
  std::vector<std::string> names;
  for (const fs::directory_entry& e : fs::directory_iterator(dir)) names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

bool has_temp_files(const fs::path& dir) {
  for (const std::string& n : file_names(dir))
    if (n.find(".tmp-") != std::string::npos) return true;
  return false;
}

}  // namespace darc::test
