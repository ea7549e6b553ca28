// darc --stats and a RenderMan 21+ Integrator request: each frame names the integrator the file
// asked for and says darc's own was used.
#include <nlohmann/json.hpp>

#include "support/darc_command.h"
#include "support/test_frames.h"

namespace darc::test {
namespace {

TEST(CliRis, StatsShowTheRequestedIntegratorAndThatDarcsWasUsed) {
  ScratchDir dir("ris-stats");
  write_file(dir / "pt.rib", "Integrator \"PxrPathTracer\" \"pt\" \"int maxPathLength\" [8]\n" +
                                 tiny_frame_rib(1, "pt.exr") + tiny_frame_rib(2, "pt2.exr"));
  write_file(dir / "plain.rib", tiny_frame_rib(1, "plain.exr"));
  const RunResult r = run_darc(dir.path(), "--stats pt.json pt.rib");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("Integrator: \"PxrPathTracer\" is recorded (--stats) but darc renders with its own integrator"),
            std::string::npos)
      << r.err;
  const nlohmann::json stats = nlohmann::json::parse(read_text_file(dir / "pt.json"));
  ASSERT_EQ(stats["frames"].size(), 2u);
  for (const nlohmann::json& frame : stats["frames"]) {
    ASSERT_TRUE(frame.contains("integrator")) << frame.dump();
    EXPECT_EQ(frame["integrator"]["requested"], "PxrPathTracer");
    EXPECT_EQ(frame["integrator"]["used"], "darc");
    EXPECT_NE(frame["integrator"]["note"].get<std::string>().find("own integrator"), std::string::npos);
  }
  ASSERT_EQ(run_darc(dir.path(), "--stats plain.json plain.rib").exit_code, 0);
  const nlohmann::json plain = nlohmann::json::parse(read_text_file(dir / "plain.json"));
  ASSERT_EQ(plain["frames"].size(), 1u);
  EXPECT_FALSE(plain["frames"][0].contains("integrator")) << "no Integrator request, no entry";
}

}  // namespace
}  // namespace darc::test
