// Inline archives (RI Spec 3.4 RiArchiveBegin/RiArchiveEnd; Maya exporters write them for
// every shared shading network or piece of geometry): the body of `ArchiveBegin "name" ...
// ArchiveEnd` is kept, not run, and `ReadArchive "name"` replays it, before any file of that
// name is looked for (as in PRMan). A body is kept as a span of the text it came from, so a
// replay reports positions in the original file and copies nothing.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <string_view>

#include "parser/lexer.h"
#include "parser/source_loc.h"

namespace darc {

struct InlineArchive {
  RibTextSpan body;      // from the first token after ArchiveBegin's arguments to ArchiveEnd
  SourceLoc defined_at;  // the ArchiveBegin
};

class InlineArchiveStore {
 public:
  // A later definition of the same name replaces the earlier one (for the ReadArchives after it).
  void define(const std::string& name, InlineArchive archive) { archives_[name] = std::move(archive); }
  const InlineArchive* find(std::string_view name) const;

 private:
  std::map<std::string, InlineArchive, std::less<>> archives_;
};

struct ArchiveBodyScan {
  bool closed = false;  // the matching ArchiveEnd was found (and consumed)
  RibTextSpan body;     // closed only
  // The first lexical error inside the body, if any: when the body is never closed it is the
  // likely cause (an unterminated string swallows the ArchiveEnd).
  std::optional<Token> lexical_error;
};

// Reads an archive's body from `lexer`, positioned just after ArchiveBegin's arguments, up to
// and including the matching ArchiveEnd; ArchiveBegin/ArchiveEnd pairs nested inside are part
// of the body. Nothing in it is interpreted: that happens at each replay.
ArchiveBodyScan scan_archive_body(Lexer& lexer);

}  // namespace darc
