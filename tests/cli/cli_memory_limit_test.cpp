// End-to-end: a scene larger than the memory darc may use fails with a clear error at the
// request that crosses the limit and writes nothing, instead of being killed by the kernel's OOM
// killer; --memory-limit sets the limit, and a real memory cgroup (what a Slurm job's --mem or a
// container sets) is found on its own.
#include <csignal>
#include <random>

#include "support/cubic_strands.h"
#include "support/darc_command.h"
#include "support/test_frames.h"

namespace darc::test {
namespace {

constexpr int kExitUsage = 2;
constexpr int kExitSceneError = 3;

// A frame of `strands` random hair strands (10 cubic Bézier segments each), 1000 per Curves
// request, rendered at 32x24 to out.exr.
std::string hair_frame(int strands) {
  constexpr int kPerRequest = 1000;
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  Vec3f root;
  const StrandPoint point = [&](int, int v) {
    if (v == 0) root = Vec3f{u(rng), u(rng), u(rng)};
    return Vec3f{root.x + 0.01f * float(v), root.y + 0.005f * float(v), root.z};
  };
  std::string rib = "Display \"out.exr\" \"file\" \"rgba\"\nFormat 32 24 1\nPixelSamples 1 1\n"
                    "Projection \"perspective\" \"fov\" [40]\nTranslate 0 0 5\nWorldBegin\nSurface \"constant\"\n";
  for (int first = 0; first < strands; first += kPerRequest) rib += cubic_strands(kPerRequest, 31, point, 0.005f);
  return rib + "WorldEnd\n";
}

TEST(CliMemoryLimit, FrameOverTheLimitIsAnErrorAtItsRequestAndWritesNothing) {
  ScratchDir dir("memory-limit");
  write_file(dir / "hair.rib", hair_frame(20000));  // 200k segments
  const RunResult r = run_darc(dir.path(), "--memory-limit 20M hair.rib");
  EXPECT_EQ(r.exit_code, kExitSceneError) << r.err;
  EXPECT_NE(r.err.find("hair.rib:8:1: error: Curves: the frame would need about"), std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("the limit is 20 MB, from --memory-limit); the frame is not rendered"), std::string::npos)
      << r.err;
  EXPECT_FALSE(fs::exists(dir / "out.exr"));
  // The same scene within a limit it fits renders.
  const RunResult fits = run_darc(dir.path(), "--memory-limit 2G hair.rib");
  EXPECT_EQ(fits.exit_code, 0) << fits.err;
  EXPECT_TRUE(fs::exists(dir / "out.exr"));
}

// The image counts too (128 bytes a pixel): a Format of 16384x16384 (32 GB) fails before the
// image is allocated, at its first geometry request, and writes nothing.
TEST(CliMemoryLimit, AnImageLargerThanTheLimitFailsBeforeItIsAllocated) {
  ScratchDir dir("memory-image");
  write_file(dir / "huge.rib",
             "Display \"huge.exr\" \"file\" \"rgba\"\nFormat 16384 16384 1\nPixelSamples 1 1\n"
             "Projection \"perspective\" \"fov\" [40]\nTranslate 0 0 5\nWorldBegin\nSphere 1 -1 1 360\nWorldEnd\n");
  const RunResult r = run_darc(dir.path(), "--memory-limit 4G huge.rib");
  EXPECT_EQ(r.exit_code, kExitSceneError) << r.err;
  EXPECT_NE(r.err.find("huge.rib:7:1: error: Sphere: the frame would need about 32.0 GB with this request (its "
                       "geometry and 32.0 GB for its image), more than the"),
            std::string::npos)
      << r.err;
  EXPECT_FALSE(fs::exists(dir / "huge.exr"));
}

TEST(CliMemoryLimit, MalformedLimitIsAUsageError) {
  ScratchDir dir("memory-limit-usage");
  write_file(dir / "scene.rib", tiny_frame_rib(1, "out.exr"));
  for (const char* bad : {"lots", "0", "-1G"}) {
    const RunResult r = run_darc(dir.path(), std::string("--memory-limit ") + bad + " scene.rib");
    EXPECT_EQ(r.exit_code, kExitUsage) << bad << ": " << r.err;
    EXPECT_NE(r.err.find("--memory-limit"), std::string::npos) << r.err;
  }
  const RunResult none = run_darc(dir.path(), "--memory-limit none scene.rib");
  EXPECT_EQ(none.exit_code, 0) << none.err;
}

// A memory cgroup made for the test under this process's own (v1 or v2), removed at scope end.
class MemoryCgroup {
 public:
  MemoryCgroup(const std::string& name, uint64_t limit_bytes) {
    std::ifstream groups("/proc/self/cgroup");
    fs::path parent;
    bool v1 = false;
    for (std::string line; std::getline(groups, line);) {
      const size_t a = line.find(':'), b = line.find(':', a + 1);
      if (a == std::string::npos || b == std::string::npos) continue;
      const std::string controllers = line.substr(a + 1, b - a - 1), path = line.substr(b + 1);
      if (controllers == "memory") {
        parent = fs::path("/sys/fs/cgroup/memory") / path.substr(1);
        v1 = true;
        break;
      }
      if (line.rfind("0::", 0) == 0) parent = fs::path("/sys/fs/cgroup") / path.substr(1);
    }
    if (parent.empty()) return;
    dir_ = parent / ("darc-test-" + name + "-" + std::to_string(::getpid()));
    std::error_code ec;
    if (!fs::create_directory(dir_, ec)) {
      why_ = "cannot create " + dir_.string() + ": " + ec.message();
      dir_.clear();
      return;
    }
    why_.clear();
    std::ofstream limit(dir_ / (v1 ? "memory.limit_in_bytes" : "memory.max"));
    limit << limit_bytes;
    limit.close();
    if (!limit) why_ = "cannot set the memory limit in " + dir_.string();
    // No swap for the group (v1: memory+swap = memory), or the kernel would swap instead of failing.
    if (v1) std::ofstream(dir_ / "memory.memsw.limit_in_bytes") << limit_bytes;
    else std::ofstream(dir_ / "memory.swap.max") << 0;
  }
  ~MemoryCgroup() {
    std::error_code ec;
    if (!dir_.empty()) fs::remove(dir_, ec);
  }
  bool usable() const { return !dir_.empty() && why_.empty(); }
  const std::string& why_not() const { return why_; }
  // A shell command that runs `command` inside the group.
  std::string inside(const std::string& command) const {
    return "sh -c 'echo $$ > " + (dir_ / "cgroup.procs").string() + " && exec " + command + "'";
  }

 private:
  fs::path dir_;
  std::string why_ = "no memory cgroup in /proc/self/cgroup";
};

TEST(CliMemoryLimit, CgroupLimitFailsTheFrameInsteadOfTheOomKiller) {
#if defined(__SANITIZE_ADDRESS__)
  GTEST_SKIP() << "AddressSanitizer's own shadow memory and quarantine make a 96 MB cgroup meaningless";
#endif
  // 600k segments: about 190 MB at their peak (docs/memory.md), twice the group's 96 MB.
  ScratchDir dir("memory-cgroup");
  write_file(dir / "hair.rib", hair_frame(60000));
  MemoryCgroup group("small", 96ull << 20);
  if (!group.usable()) GTEST_SKIP() << "no memory cgroup can be made here (needs root): " << group.why_not();
  // Appended from the left: GCC 12 wrongly warns (-Wrestrict, its bug 105329) on "literal" + string.
  const std::string darc = std::string("\"").append(DARC_BINARY).append("\" --quiet hair.rib");
  const std::string cmd = "cd '" + dir.path().string() + "' && " + group.inside(darc) + " 2> err.txt";
  const int status = std::system(cmd.c_str());
  const std::string err = read_text_file(dir / "err.txt");
  ASSERT_TRUE(WIFEXITED(status)) << "killed (by the OOM killer?): " << err;
  // sh's exit status is darc's; 128 + 9 would be a SIGKILL seen by sh.
  EXPECT_EQ(WEXITSTATUS(status), kExitSceneError) << err;
  EXPECT_NE(err.find("error: Curves: the frame would need about"), std::string::npos) << err;
  EXPECT_NE(err.find("cgroup"), std::string::npos) << "the message says where the limit comes from: " << err;
  EXPECT_FALSE(fs::exists(dir / "out.exr"));

  // The same frame in a group large enough renders: the limit does not refuse what fits.
  MemoryCgroup large("large", 1ull << 30);
  ASSERT_TRUE(large.usable()) << large.why_not();
  const std::string fits = "cd '" + dir.path().string() + "' && " + large.inside(darc) + " 2> err.txt";
  const int fits_status = std::system(fits.c_str());
  EXPECT_TRUE(WIFEXITED(fits_status) && WEXITSTATUS(fits_status) == 0) << read_text_file(dir / "err.txt");
  EXPECT_TRUE(fs::exists(dir / "out.exr"));
}

}  // namespace
}  // namespace darc::test
