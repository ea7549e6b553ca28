// The free space darc leaves on a file system. A RIB can ask for many frames of large images
// (and a render farm runs many of them at once); a full disk breaks everything else the user
// runs there. So before an image is written, darc checks that writing it leaves at least a
// reserve free, and refuses the write (an I/O error, exit 1, no file) when it would not.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

namespace darc {

// The default reserve: 1 % of the file system, as the share a disk keeps for repairs is counted
// (ext4 keeps 5 % for root), but never more than 1 GiB, so a large disk is not held back for a
// reserve far beyond one image.
inline constexpr std::uint64_t kMaxDefaultDiskReserve = std::uint64_t(1) << 30;
inline constexpr std::uint64_t kDefaultDiskReserveDivisor = 100;  // 1 %

// What an image file takes at most, for the check before it is written: 4 bytes a channel value
// (darc writes half floats or 8 bits, compressed, so less) and a header's worth of metadata.
inline constexpr std::uint64_t kImageHeaderBound = std::uint64_t(1) << 20;
inline std::uint64_t image_file_bound(std::uint64_t channel_values) { return channel_values * 4 + kImageHeaderBound; }

struct DiskSpace {
  std::uint64_t available = 0;  // bytes this user may still write
  std::uint64_t size = 0;       // the file system's size
};

// The space of the file system holding `folder`; nullopt when it cannot be read (the folder does
// not exist: the write then fails on its own).
std::optional<DiskSpace> disk_space(const std::string& folder);

// min(1 % of the file system, 1 GiB).
std::uint64_t default_disk_reserve(const DiskSpace& space);

// "" when writing `bytes` leaves at least `reserve` free; else why not, for the message.
// `reserve_source` says where the reserve comes from.
std::string disk_reserve_shortfall(const DiskSpace& space, std::uint64_t bytes, std::uint64_t reserve,
                                   const std::string& reserve_source);

}  // namespace darc
