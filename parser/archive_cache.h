// The run's parsed archives: each file ReadArchive reads is parsed once, into the RiTarget calls
// and the diagnostics its text produces (in order), and replayed from memory at every later
// ReadArchive of it, while the file and every archive it read in turn keep their size and
// modification time. A 50-frame camera move over one heavy hair archive parses it once.
//
// The parse of an archive depends on what the including text declared (inline declarations)
// and on the archive search path (for the archives it reads), so an entry is only replayed when
// both are what they were when it was parsed; its own declarations and search path changes are
// replayed with it.
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "parser/call_recorder.h"
#include "parser/diagnostics.h"
#include "parser/request_reader.h"

namespace darc {

// What says a file is unchanged: its size and modification time (as make and ccache check).
struct FileStamp {
  std::string path;
  std::uintmax_t size = 0;
  std::int64_t modified_ns = 0;
  bool operator==(const FileStamp&) const = default;
};
// nullopt when the file cannot be examined.
std::optional<FileStamp> stamp_file(const std::string& path);

struct RecordedArchive {
  // One step of the replay: a call for the target, or a diagnostic its parse reported.
  struct Event {
    CallRecorder::Entry call;               // call.call is empty for a diagnostic
    std::optional<Diagnostic> diagnostic;
  };
  std::vector<Event> events;
  std::vector<FileStamp> files;  // the archive, then every archive its parse read
  DeclarationMap declarations_before, declarations_after;
  std::vector<std::string> search_path_before, search_path_after;
  uint64_t serial = 0;  // unique per stored entry in the run (ArchiveCache::store sets it)
  // The replayed_request id of event i (never 0).
  uint64_t request_id(size_t i) const { return (serial << 32) | uint64_t(i + 1); }
};

class ArchiveCache {
 public:
  // The entry of the archive at `canonical_path`, when every file it depends on is unchanged
  // and it was parsed with these declarations and this search path; else nullptr.
  std::shared_ptr<const RecordedArchive> find(const std::string& canonical_path, const DeclarationMap& declarations,
                                              const std::vector<std::string>& search_path) const;
  std::shared_ptr<const RecordedArchive> store(const std::string& canonical_path, RecordedArchive archive);

  // For --stats and tests: archives parsed (misses, including replaced entries) and replayed.
  std::int64_t parses() const { return parses_; }
  std::int64_t replays() const { return replays_; }
  void count_replay() { ++replays_; }

 private:
  std::map<std::string, std::shared_ptr<const RecordedArchive>> entries_;
  std::int64_t parses_ = 0, replays_ = 0;
  uint64_t next_serial_ = 1;
};

}  // namespace darc
