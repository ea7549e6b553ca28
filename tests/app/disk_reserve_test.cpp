// The disk reserve: 1 % of the file system up to 1 GiB by default, and a write is refused when
// it would leave less than the reserve free.
#include "app/disk_reserve.h"

#include <gtest/gtest.h>

namespace darc {
namespace {

constexpr std::uint64_t GiB = std::uint64_t(1) << 30;

TEST(DiskReserve, TheDefaultIsOnePercentUpToOneGiB) {
  EXPECT_EQ(default_disk_reserve(DiskSpace{0, 10 * GiB}), 10 * GiB / 100);
  EXPECT_EQ(default_disk_reserve(DiskSpace{0, 100 * GiB}), GiB);
  EXPECT_EQ(default_disk_reserve(DiskSpace{0, 1000 * GiB}), GiB);
}

TEST(DiskReserve, AWriteMustLeaveTheReserve) {
  const DiskSpace space{5 * GiB, 100 * GiB};
  EXPECT_EQ(disk_reserve_shortfall(space, 4 * GiB, GiB, "test"), "");
  EXPECT_EQ(disk_reserve_shortfall(space, 4 * GiB + 1, GiB, "test").rfind("writing it (up to 4.0 GB) would leave", 0),
            0u);
  EXPECT_EQ(disk_reserve_shortfall(space, 6 * GiB, 0, "test"),
            "writing it (up to 6.0 GB) would leave nothing free on its file system, less than the disk reserve of "
            "0 kB (test)");
}

TEST(DiskReserve, TheFileSystemOfAFolderIsRead) {
  const std::optional<DiskSpace> space = disk_space(".");
  ASSERT_TRUE(space);
  EXPECT_GT(space->size, 0u);
  EXPECT_LE(space->available, space->size);
  EXPECT_FALSE(disk_space("/nonexistent/folder"));
}

}  // namespace
}  // namespace darc
