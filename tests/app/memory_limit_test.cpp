// The memory darc may use, from what Linux reports (app/memory_limit.h): the smallest of the
// machine's available memory, the cgroup's limit and the rlimits, each as a total for the process.
#include "app/memory_limit.h"

#include <gtest/gtest.h>

namespace darc {
namespace {

constexpr uint64_t kMiB = uint64_t(1) << 20;

MemoryLimitInputs machine_with_available_mib(uint64_t mib) {
  MemoryLimitInputs in;
  in.meminfo = "MemTotal:       24000000 kB\nMemFree:        1000 kB\nMemAvailable:   " + std::to_string(mib * 1024) +
               " kB\nBuffers:        1 kB\n";
  in.process_resident = 10 * kMiB;
  in.process_virtual = 300 * kMiB;
  in.process_data = 40 * kMiB;
  return in;
}

TEST(MemoryLimit, AvailableMemoryCountsWhatTheProcessAlreadyHolds) {
  std::optional<MemoryLimit> limit = memory_limit(machine_with_available_mib(1000));
  ASSERT_TRUE(limit);
  EXPECT_EQ(limit->bytes, 1010 * kMiB);
  EXPECT_NE(limit->source.find("MemAvailable"), std::string::npos);
}

TEST(MemoryLimit, CgroupV2LimitLessWhatTheGroupsOtherProcessesUse) {
  MemoryLimitInputs in = machine_with_available_mib(20000);
  in.cgroup_max = std::to_string(2048 * kMiB) + "\n";
  in.cgroup_current = std::to_string(110 * kMiB) + "\n";  // this process's 10 MiB and 100 of others
  std::optional<MemoryLimit> limit = memory_limit(in);
  ASSERT_TRUE(limit);
  EXPECT_EQ(limit->bytes, 1948 * kMiB);
  EXPECT_NE(limit->source.find("cgroup"), std::string::npos);
}

TEST(MemoryLimit, UnlimitedCgroupsInEitherVersionAreNoLimit) {
  for (const char* none : {"max\n", "9223372036854771712\n"}) {
    MemoryLimitInputs in = machine_with_available_mib(500);
    in.cgroup_max = none;
    in.cgroup_current = "123456789\n";
    std::optional<MemoryLimit> limit = memory_limit(in);
    ASSERT_TRUE(limit);
    EXPECT_NE(limit->source.find("MemAvailable"), std::string::npos) << none;
  }
}

TEST(MemoryLimit, RlimitsCountFromWhatTheProcessHasMapped) {
  MemoryLimitInputs in = machine_with_available_mib(20000);
  in.rlimit_as = 800 * kMiB;  // 300 MiB mapped already: 500 more, on top of the 10 resident
  std::optional<MemoryLimit> limit = memory_limit(in);
  ASSERT_TRUE(limit);
  EXPECT_EQ(limit->bytes, 510 * kMiB);
  EXPECT_NE(limit->source.find("ulimit -v"), std::string::npos);
  in.rlimit_data = 100 * kMiB;  // 40 used: 60 more
  limit = memory_limit(in);
  ASSERT_TRUE(limit);
  EXPECT_EQ(limit->bytes, 70 * kMiB);
  EXPECT_NE(limit->source.find("ulimit -d"), std::string::npos);
}

TEST(MemoryLimit, NothingReadableIsNoLimit) { EXPECT_FALSE(memory_limit(MemoryLimitInputs{})); }

TEST(MemoryLimit, ThisProcessHasOne) {
  // Linux always reports MemAvailable; the limit is at least what the process holds.
  const MemoryLimitInputs in = this_process_memory_inputs();
  std::optional<MemoryLimit> limit = memory_limit(in);
  ASSERT_TRUE(limit);
  EXPECT_GE(limit->bytes, in.process_resident);
  EXPECT_GT(in.process_resident, 0u);
}

TEST(MemoryLimit, ByteSizesInSlurmsUnits) {
  EXPECT_EQ(parse_byte_size("123456"), 123456u);
  EXPECT_EQ(parse_byte_size("300k"), 300u * 1024);
  EXPECT_EQ(parse_byte_size("500M"), 500 * kMiB);
  EXPECT_EQ(parse_byte_size("1.5G"), 1536 * kMiB);
  EXPECT_EQ(parse_byte_size("2t"), uint64_t(2) << 40);
  for (const char* bad : {"", "G", "-5M", "12x", "1e30G", "nan"}) EXPECT_FALSE(parse_byte_size(bad)) << bad;
}

}  // namespace
}  // namespace darc
