#include "app/disk_reserve.h"

#include <sys/statvfs.h>

#include <algorithm>

#include "core/scene/frame_memory.h"

namespace darc {

std::optional<DiskSpace> disk_space(const std::string& folder) {
  struct statvfs fs {};
  if (::statvfs(folder.c_str(), &fs) != 0) return std::nullopt;
  return DiskSpace{std::uint64_t(fs.f_bavail) * fs.f_frsize, std::uint64_t(fs.f_blocks) * fs.f_frsize};
}

std::uint64_t default_disk_reserve(const DiskSpace& space) {
  return std::min(kMaxDefaultDiskReserve, space.size / kDefaultDiskReserveDivisor);
}

std::string disk_reserve_shortfall(const DiskSpace& space, std::uint64_t bytes, std::uint64_t reserve,
                                   const std::string& reserve_source) {
  if (space.available >= bytes && space.available - bytes >= reserve) return {};
  return "writing it (up to " + format_bytes(bytes) + ") would leave " +
         (space.available > bytes ? format_bytes(space.available - bytes) : std::string("nothing")) +
         " free on its file system, less than the disk reserve of " + format_bytes(reserve) + " (" + reserve_source +
         ")";
}

}  // namespace darc
