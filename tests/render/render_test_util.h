// Helpers for end-to-end tests: run the darc command in a scratch directory and read images.
#pragma once

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imageio.h>

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <optional>
#include <string>
#include <vector>

namespace darc::test {

namespace fs = std::filesystem;

inline fs::path shared_ribs() { return fs::path(DARC_SHARED_RIBS_DIR) / "aqsis"; }
inline bool have_shared_ribs() { return fs::is_directory(shared_ribs()); }

// A fresh directory under the system temp dir, removed at scope end.
class ScratchDir {
 public:
  explicit ScratchDir(const std::string& name) {
    path_ = fs::temp_directory_path() / ("darc-test-" + name + "-" + std::to_string(::getpid()));
    fs::remove_all(path_);
    fs::create_directories(path_);
  }
  ~ScratchDir() {
    std::error_code ec;
    fs::remove_all(path_, ec);
  }
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

inline std::string read_text_file(const fs::path& p) {
  std::ifstream f(p, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>());
}

// Runs `darc ARGS` with the working directory `cwd` and options.environment; captures stdout and
// stderr (into stdout.txt / stderr.txt in `cwd`). stderr is a file, so darc sees no terminal.
inline RunResult run_darc(const fs::path& cwd, const std::string& args, const RunOptions& options) {
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

inline RunResult run_darc(const fs::path& cwd, const std::string& args) { return run_darc(cwd, args, RunOptions{}); }

inline void write_file(const fs::path& p, const std::string& text) {
  std::ofstream f(p, std::ios::binary);
  f << text;
}

// The world of a small test frame: a constant-coloured S-shaped cubic curve (width 0.1) in
// front of a sphere of radius 0.5 at the origin, seen from 5 units away with a 40 degree fov.
inline std::string tiny_world_rib() {
  return "WorldBegin\n"
         "  Surface \"constant\"\n"
         "  Color [1 0.5 0.25]\n"
         "  Curves \"cubic\" [4] \"nonperiodic\" \"P\" [-1 -1 0  -0.3 0.5 -0.5  0.3 -0.5 -0.5  1 1 0]"
         " \"constantwidth\" [0.1]\n"
         "  Color [0.2 0.4 0.9]\n"
         "  Sphere 0.5 -0.5 0.5 360\n"
         "WorldEnd\n";
}

// One frame of the tiny scene: FrameBegin `frame`, Display `display` with `mode`, WIDTHxHEIGHT,
// PixelSamples 1 1.
inline std::string tiny_frame_rib(int frame, const std::string& display, const std::string& mode = "rgba",
                                  int width = 32, int height = 24) {
  return "FrameBegin " + std::to_string(frame) + "\n" + "Display \"" + display + "\" \"file\" \"" + mode + "\"\n" +
         "Format " + std::to_string(width) + " " + std::to_string(height) + " 1\n" +
         "PixelSamples 1 1\n"
         "Projection \"perspective\" \"fov\" [40]\n"
         "Translate 0 0 5\n" +
         tiny_world_rib() + "FrameEnd\n";
}

// The names of the files in `dir` (not recursive), sorted.
inline std::vector<std::string> file_names(const fs::path& dir) {
  std::vector<std::string> names;
  for (const fs::directory_entry& e : fs::directory_iterator(dir)) names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

// True when `dir` holds a temporary image (ImageWriter writes "stem.tmp-PID-N.ext", then renames).
inline bool has_temp_files(const fs::path& dir) {
  for (const std::string& n : file_names(dir))
    if (n.find(".tmp-") != std::string::npos) return true;
  return false;
}

// Pixels as float RGBA (or fewer channels), row-major.
struct Pixels {
  int width = 0, height = 0, channels = 0;
  std::vector<float> v;
  float at(int x, int y, int c) const { return v[(size_t(y) * width + x) * channels + c]; }
  // Same size, same channels, every value bitwise equal (as floats read back).
  bool identical_to(const Pixels& o) const {
    return width == o.width && height == o.height && channels == o.channels && v.size() == o.v.size() &&
           std::memcmp(v.data(), o.v.data(), v.size() * sizeof(float)) == 0;
  }
};

inline bool read_image(const fs::path& p, Pixels& out) {
  OIIO::ImageBuf buf(p.string());
  if (!buf.read(0, 0, true, OIIO::TypeDesc::FLOAT)) return false;
  const OIIO::ImageSpec& s = buf.spec();
  out.width = s.width;
  out.height = s.height;
  out.channels = s.nchannels;
  out.v.resize(size_t(s.width) * s.height * s.nchannels);
  return buf.get_pixels(OIIO::ROI(0, s.width, 0, s.height, 0, 1, 0, s.nchannels), OIIO::TypeDesc::FLOAT, out.v.data());
}

// The header (size, channels, metadata) of an image file; nullopt when it does not open.
inline std::optional<OIIO::ImageSpec> read_image_header(const fs::path& p) {
  auto in = OIIO::ImageInput::open(p.string());
  if (!in) return std::nullopt;
  return in->spec();
}

}  // namespace darc::test
