// Members of zip files as RIB archives: PRMan's "cache.zip!path/in/zip.rib" (RenderMan for
// Maya 21+ writes its geometry into zip caches and reads it back through DelayedReadArchive).
// Read with libzip, within the same limits as files (RibReadLimits: a member that inflates past
// the most a RIB text may be is refused before it is read).
#pragma once

#include <optional>
#include <string>

#include "parser/rib_file.h"

namespace darc {

// The zip file and the member a name like "dir/cache.zip!sub/shape.rib" names (split at the first
// ".zip!", in any case); nullopt for other names.
struct ZipMemberName {
  std::string zip;     // "dir/cache.zip"
  std::string member;  // "sub/shape.rib"
};
std::optional<ZipMemberName> split_zip_member(const std::string& name);

// Reads member `member` of the zip file at `zip_path` into `text`. Returns false and sets `error`
// to why (without the names) when the zip cannot be opened, has no such member, the member is
// larger than limits.max_bytes, or fails while it is read. A member whose name ends in ".gz" is
// refused (RfM stores its members plain; the zip compresses them already).
bool read_zip_member(const std::string& zip_path, const std::string& member, std::string& text, std::string& error,
                     const RibReadLimits& limits = {});

}  // namespace darc
