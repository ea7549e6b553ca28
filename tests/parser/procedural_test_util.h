// Helpers for the procedural tests: a scratch folder that can hold generator programs (small
// shell scripts), and a parse whose target records the bounds it is asked about.
#pragma once

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <memory>
#include <string>

#include "recording_target.h"

namespace darc::test {

namespace fs = std::filesystem;

// A fresh folder under the temp dir, named after the test, removed at the end of it.
class ScratchFolder {
 public:
  ScratchFolder() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    path_ = fs::temp_directory_path() / (std::string("darc_proc_") + info->test_suite_name() + "_" + info->name() +
                                         "_" + std::to_string(::getpid()));
    fs::remove_all(path_);
    fs::create_directories(path_);
  }
  ~ScratchFolder() {
    std::error_code ec;
    fs::remove_all(path_, ec);
  }
  ScratchFolder(const ScratchFolder&) = delete;
  ScratchFolder& operator=(const ScratchFolder&) = delete;

  const fs::path& path() const { return path_; }
  std::string str() const { return path_.string(); }
  fs::path operator/(const std::string& name) const { return path_ / name; }

  std::string write(const std::string& name, const std::string& text) const {
    const fs::path p = path_ / name;
    fs::create_directories(p.parent_path());
    std::ofstream(p, std::ios::binary) << text;
    return p.string();
  }
  // An executable /bin/sh script; `body` follows the #! line.
  std::string write_program(const std::string& name, const std::string& body) const {
    const std::string p = write(name, "#!/bin/sh\n" + body);
    fs::permissions(p, fs::perms::owner_all | fs::perms::group_read | fs::perms::group_exec);
    return p;
  }

 private:
  fs::path path_;
};

// A RecordingTarget that answers procedural_bound with `answer` and keeps the bounds asked about.
class BoundRecordingTarget : public RecordingTarget {
 public:
  ProceduralBound answer;
  std::vector<std::array<double, 6>> bounds;
  ProceduralBound procedural_bound(const std::array<double, 6>& bound, const SourceLoc&) override {
    bounds.push_back(bound);
    return answer;
  }
};

struct ProceduralParse {
  BoundRecordingTarget target;
  Diagnostics diag{[](const Diagnostic&) {}};
  bool ok = false;

  std::vector<Diagnostic> of(Severity s) const {
    std::vector<Diagnostic> out;
    for (const Diagnostic& d : diag.all())
      if (d.severity == s) out.push_back(d);
    return out;
  }
  std::vector<Diagnostic> errors() const { return of(Severity::Error); }
  std::vector<Diagnostic> warnings() const { return of(Severity::Warning); }
  // The first error's "position: message" (for failure output).
  std::string first_error() const {
    const auto e = errors();
    return e.empty() ? std::string("no error") : e[0].str();
  }
};

// Parses `text` as the file `name`; `setup` configures the parser first (folders, limits) and
// `answer` is what the target says about every bound.
inline std::unique_ptr<ProceduralParse> parse_procedural(const std::string& text, const std::string& name,
                                                         const std::function<void(RibParser&)>& setup = {},
                                                         ProceduralBound answer = {}) {
  auto r = std::make_unique<ProceduralParse>();
  r->target.answer = answer;
  RibParser parser(r->target, r->diag);
  if (setup) setup(parser);
  r->ok = parser.parse_string(text, name);
  return r;
}

inline bool contains(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

}  // namespace darc::test
