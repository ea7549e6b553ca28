// A RiTarget that keeps every call it is given, in order, to be replayed into another target
// later: the parsed form of an archive that the run reads many times (archive_cache.h). Each
// call keeps copies of its arguments, so a replay hands the target the same parameter lists
// every time.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "parser/ri_target.h"

namespace darc {

class CallRecorder : public RiTarget {
 public:
  using Call = std::function<void(RiTarget&)>;
  // What a recorded call is: the call itself, and its request and position for messages.
  struct Entry {
    Call call;
    std::string request;
    SourceLoc loc;
  };
  // Each call is handed to `sink` as it arrives (so that it can be ordered with the diagnostics
  // of the same text).
  explicit CallRecorder(std::function<void(Entry)> sink) : sink_(std::move(sink)) {}

#include "parser/ri_target_overrides.inc"

 private:
  void keep(std::string request, const SourceLoc& loc, Call call) {
    sink_(Entry{std::move(call), std::move(request), loc});
  }
  std::function<void(Entry)> sink_;
};

}  // namespace darc
