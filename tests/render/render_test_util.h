// Helpers for end-to-end tests: run the darc command in a scratch directory and read images.
#pragma once

#include <OpenImageIO/imagebuf.h>

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
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
};

// Runs `darc ARGS` with the working directory `cwd`; captures stderr.
inline RunResult run_darc(const fs::path& cwd, const std::string& args) {
  fs::path errfile = cwd / "stderr.txt";
  std::string cmd = "cd '" + cwd.string() + "' && '" + std::string(DARC_BINARY) + "' --quiet " + args + " 2> '" +
                    errfile.string() + "'";
  int status = std::system(cmd.c_str());
  RunResult r;
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  std::ifstream f(errfile);
  r.err.assign(std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>());
  return r;
}

inline void write_file(const fs::path& p, const std::string& text) {
  std::ofstream f(p, std::ios::binary);
  f << text;
}

// Pixels as float RGBA (or fewer channels), row-major.
struct Pixels {
  int width = 0, height = 0, channels = 0;
  std::vector<float> v;
  float at(int x, int y, int c) const { return v[(size_t(y) * width + x) * channels + c]; }
};

inline bool read_image(const fs::path& p, Pixels& out) {
  OIIO::ImageBuf buf(p.string());
  if (!buf.read(0, 0, true, OIIO::TypeDesc::FLOAT)) return false;
  const OIIO::ImageSpec& s = buf.spec();
  out.width = s.width;
  out.height = s.height;
  out.channels = s.nchannels;
  out.v.resize(size_t(s.width) * s.height * s.nchannels);
  return buf.get_pixels(OIIO::ROI(0, s.width, 0, s.height, 0, 1, 0, s.nchannels), OIIO::TypeDesc::FLOAT,
                        out.v.data());
}

}  // namespace darc::test
