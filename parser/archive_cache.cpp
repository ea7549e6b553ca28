#include "parser/archive_cache.h"

#include <chrono>
#include <filesystem>

namespace darc {

std::optional<FileStamp> stamp_file(const std::string& path) {
  std::error_code ec;
  const std::uintmax_t size = std::filesystem::file_size(path, ec);
  if (ec) return std::nullopt;
  const auto modified = std::filesystem::last_write_time(path, ec);
  if (ec) return std::nullopt;
  return FileStamp{path, size,
                   std::chrono::duration_cast<std::chrono::nanoseconds>(modified.time_since_epoch()).count()};
}

std::shared_ptr<const RecordedArchive> ArchiveCache::find(const std::string& canonical_path,
                                                          const DeclarationMap& declarations,
                                                          const std::vector<std::string>& search_path) const {
  auto it = entries_.find(canonical_path);
  if (it == entries_.end()) return nullptr;
  const RecordedArchive& a = *it->second;
  if (a.declarations_before != declarations || a.search_path_before != search_path) return nullptr;
  for (const FileStamp& f : a.files)
    if (stamp_file(f.path) != f) return nullptr;
  return it->second;
}

std::shared_ptr<const RecordedArchive> ArchiveCache::store(const std::string& canonical_path,
                                                           RecordedArchive archive) {
  ++parses_;
  archive.serial = next_serial_++;
  auto entry = std::make_shared<const RecordedArchive>(std::move(archive));
  entries_[canonical_path] = entry;
  return entry;
}

}  // namespace darc
