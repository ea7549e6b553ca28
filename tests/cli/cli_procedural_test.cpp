// End-to-end: procedurals from the darc command. The example generator scene renders; a scene
// cannot start a program outside the procedural search path; --procedural-path trusts a folder,
// --procedural-timeout bounds a request, and a generator's standard error reaches darc's, marked.
#include "render/render_test_util.h"

namespace darc::test {
namespace {

constexpr int kExitOk = 0;
constexpr int kExitUsage = 2;
constexpr int kExitSceneError = 3;

void write_program(const fs::path& p, const std::string& body) {
  fs::create_directories(p.parent_path());
  write_file(p, "#!/bin/sh\n" + body);
  fs::permissions(p, fs::perms::owner_all);
}

// The tiny frame with `procedurals` in its world block, before the tiny scene's own geometry.
std::string frame_with(const std::string& procedurals) {
  return "Display \"out.exr\" \"file\" \"rgba\"\nFormat 32 24 1\nPixelSamples 1 1\n"
         "Projection \"perspective\" \"fov\" [40]\nTranslate 0 0 5\nWorldBegin\n" +
         procedurals + "WorldEnd\n";
}

TEST(CliProcedural, TheGrassExampleRenders) {
  ScratchDir dir("grass");
  const std::string scene = std::string(DARC_SOURCE_DIR) + "/scenes/procedural/grass.rib";
  RunResult r = run_darc(dir.path(), "--res 64x48 --pixel-samples 1 -o grass.exr '" + scene + "'");
  ASSERT_EQ(r.exit_code, kExitOk) << r.err;
  EXPECT_EQ(r.err, "") << "no warning or error";
  Pixels p;
  ASSERT_TRUE(read_image(dir / "grass.exr", p));
  // The blades are green (the ground is brown, the sky empty): many covered pixels where green
  // leads red clearly.
  int green = 0;
  for (int y = 0; y < p.height; ++y)
    for (int x = 0; x < p.width; ++x)
      if (p.at(x, y, 3) > 0.5f && p.at(x, y, 1) > p.at(x, y, 0) + 0.1f) ++green;
  EXPECT_GT(green, p.width * p.height / 10) << green << " green pixels";
}

TEST(CliProcedural, ASceneCannotStartAProgramOutsideTheSearchPath) {
  ScratchDir dir("refused");
  write_program(dir / "gen.sh", "touch started\nprintf 'Sphere 1 -1 1 360\\n\\377'\n");
  write_file(dir / "scene.rib", frame_with("Procedural \"RunProgram\" [\"./gen.sh\" \"\"] [-1 1 -1 1 -1 1]\n"
                                           "Procedural \"RunProgram\" [\"/bin/sh -c 'touch started'\" \"\"] "
                                           "[-1 1 -1 1 -1 1]\n"));
  RunResult r = run_darc(dir.path(), "scene.rib");
  EXPECT_EQ(r.exit_code, kExitSceneError) << r.err;
  EXPECT_NE(r.err.find("scene.rib:7:1: error: Procedural: RunProgram: program \"./gen.sh\" refused"), std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("scene.rib:8:1: error: Procedural: RunProgram: program \"/bin/sh\" refused"), std::string::npos)
      << r.err;
  EXPECT_FALSE(fs::exists(dir / "started")) << "a refused program never runs";
  // The frame renders without what the procedurals would have added.
  const std::optional<OIIO::ImageSpec> header = read_image_header(dir / "out.exr");
  ASSERT_TRUE(header);
  EXPECT_EQ(header->get_int_attribute("darc:errors"), 2);
}

TEST(CliProcedural, ProceduralPathTrustsAFolderAndTheTimeoutStopsASlowProgram) {
  ScratchDir dir("flags");
  write_program(dir / "bin/ok.sh", "echo 'made a sphere' >&2\nprintf 'Sphere 0.5 -0.5 0.5 360\\n\\377'\n");
  write_program(dir / "bin/slow.sh", "sleep 30\n");
  write_file(dir / "scene.rib", frame_with("Procedural \"RunProgram\" [\"ok.sh\" \"\"] [-1 1 -1 1 -1 1]\n"
                                           "Procedural \"RunProgram\" [\"slow.sh\" \"\"] [-1 1 -1 1 -1 1]\n"));
  RunResult r = run_darc(dir.path(), "--procedural-path bin --procedural-timeout 0.2 scene.rib");
  EXPECT_EQ(r.exit_code, kExitSceneError) << r.err;
  EXPECT_NE(r.err.find("RunProgram \"ok.sh\" (stderr): made a sphere\n"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("scene.rib:8:1: error: Procedural: RunProgram \"slow.sh\": did not answer within 0.2 s"),
            std::string::npos)
      << r.err;
  // --cat prints what the generator answered, in place of the request.
  RunResult cat = run_darc(dir.path(), "--cat --procedural-path bin --procedural-timeout 0.2 scene.rib");
  EXPECT_NE(cat.out.find("AttributeBegin\n    Sphere 0.5 -0.5 0.5 360\n  AttributeEnd\n"), std::string::npos)
      << cat.out;
}

TEST(CliProcedural, ProceduralFlagsAreCheckedAsUsage) {
  ScratchDir dir("usage");
  write_file(dir / "scene.rib", frame_with(""));
  for (const char* args : {"--procedural-path missing scene.rib", "--procedural-timeout 0 scene.rib",
                           "--procedural-timeout soon scene.rib"}) {
    SCOPED_TRACE(args);
    RunResult r = run_darc(dir.path(), args);
    EXPECT_EQ(r.exit_code, kExitUsage) << r.err;
    EXPECT_FALSE(fs::exists(dir / "out.exr"));
  }
  // Repeated, each takes one folder (the scene file is not swallowed as a second one).
  fs::create_directories(dir / "a");
  fs::create_directories(dir / "b");
  RunResult r = run_darc(dir.path(), "--procedural-path a --procedural-path b scene.rib");
  EXPECT_EQ(r.exit_code, kExitOk) << r.err;
}

}  // namespace
}  // namespace darc::test
