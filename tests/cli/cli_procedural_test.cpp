// End-to-end: procedurals from the darc command. The example generator scene renders when the
// user allows its folder; a scene cannot start a program outside the folders the user allowed
// (--procedural-path, DARC_PROCEDURAL_PATH), whatever its own search path says, unless the user
// trusts it (--trust-rib); --procedural-timeout bounds a request, and a generator's standard
// error reaches darc's, marked.
#include <dlfcn.h>
#include <zlib.h>

#include "support/darc_command.h"
#include "support/image_files.h"

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
  const std::string folder = std::string(DARC_SOURCE_DIR) + "/scenes/procedural";
  RunResult r = run_darc(dir.path(), "--res 64x48 --pixel-samples 1 -o grass.exr --procedural-path '" + folder +
                                         "' '" + folder + "/grass.rib'");
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

// Without --procedural-path the example's own search path (".", its folder) is not enough: the
// user has allowed nothing, so the folder is dropped and the generator does not run.
TEST(CliProcedural, TheGrassExampleNeedsItsFolderAllowed) {
  ScratchDir dir("grass-refused");
  const std::string scene = std::string(DARC_SOURCE_DIR) + "/scenes/procedural/grass.rib";
  RunResult r = run_darc(dir.path(), "--res 16x12 --pixel-samples 1 -o grass.exr '" + scene + "'");
  EXPECT_EQ(r.exit_code, kExitSceneError) << r.err;
  EXPECT_NE(r.err.find("grass.rib:6:1: warning: Option: procedural folder"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("allow it with --procedural-path"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("grass.rib:19:3: error: Procedural: RunProgram: program \"grass.py\" refused: no folder is allowed"),
            std::string::npos)
      << r.err;
}

// The issue as it was reported: the scene names /usr/bin itself and runs touch.
TEST(CliProcedural, ASceneCannotRunASystemProgramByNamingItsFolder) {
  ScratchDir dir("issue");
  fs::create_directories(dir / "bin");
  write_file(dir / "scene.rib", "Option \"searchpath\" \"procedural\" [\"/usr/bin:/bin:@\"]\n" +
                                    frame_with("Procedural \"RunProgram\" [\"touch touched\" \"\"] [-1 1 -1 1 -1 1]\n"));
  for (const char* args : {"scene.rib", "--procedural-path bin scene.rib"}) {
    SCOPED_TRACE(args);
    RunResult r = run_darc(dir.path(), args);
    EXPECT_EQ(r.exit_code, kExitSceneError) << r.err;
    EXPECT_FALSE(fs::exists(dir / "touched")) << "touch ran";
    EXPECT_NE(r.err.find("scene.rib:1:1: warning: Option: procedural folder \"/usr/bin\" dropped"), std::string::npos)
        << r.err;
    EXPECT_NE(r.err.find("scene.rib:8:1: error: Procedural: RunProgram: program \"touch\""), std::string::npos)
        << r.err;
  }
  // --trust-rib: the user vouches for the file; touch runs (and writes no RIB: an error), and
  // darc says which folders it trusted.
  RunResult trusted = run_darc(dir.path(), "--trust-rib scene.rib");
  EXPECT_TRUE(fs::exists(dir / "touched"));
  EXPECT_NE(trusted.err.find("scene.rib:1:1: warning: Option: trusting the procedural folder \"/usr/bin\" that the "
                             "RIB chose (--trust-rib)"),
            std::string::npos)
      << trusted.err;
}

// DARC_PROCEDURAL_PATH is the user's standing choice, as --procedural-path is for one run; a
// folder in it that does not exist is reported.
TEST(CliProcedural, TheEnvironmentVariableAllowsFolders) {
  ScratchDir dir("env");
  write_program(dir / "a/one.sh", "printf 'Sphere 0.5 -0.5 0.5 360\\n\\377'\n");
  write_program(dir / "b/two.sh", "printf 'Sphere 0.4 -0.4 0.4 360\\n\\377'\n");
  write_file(dir / "scene.rib", frame_with("Procedural \"RunProgram\" [\"one.sh\" \"\"] [-1 1 -1 1 -1 1]\n"
                                           "Procedural \"RunProgram\" [\"two.sh\" \"\"] [-1 1 -1 1 -1 1]\n"));
  RunOptions env;
  env.environment = "DARC_PROCEDURAL_PATH='" + (dir / "a").string() + "::" + (dir / "missing").string() + "'";
  RunResult r = run_darc(dir.path(), "--procedural-path b scene.rib", env);
  EXPECT_EQ(r.exit_code, kExitOk) << r.err;
  EXPECT_NE(r.err.find("darc: warning: DARC_PROCEDURAL_PATH: \"" + (dir / "missing").string() +
                       "\" is not a folder: ignored"),
            std::string::npos)
      << r.err;
  RunResult without = run_darc(dir.path(), "--procedural-path b scene.rib");
  EXPECT_EQ(without.exit_code, kExitSceneError) << without.err;
  EXPECT_NE(without.err.find("program \"one.sh\" is not in the procedural search path"), std::string::npos)
      << without.err;
}

// DynamicLoad names native code; darc never loads it. The dynamic loader reports every library it
// opens (LD_DEBUG=files), dlopen's included: a real library (zlib's, copied) must not be among
// them, even with --trust-rib.
TEST(CliProcedural, DynamicLoadNeverLoadsTheLibrary) {
  ScratchDir dir("dynamicload");
  Dl_info info{};
  ASSERT_NE(::dladdr(reinterpret_cast<void*>(&zlibVersion), &info), 0);
  fs::copy_file(info.dli_fname, dir / "hair.so");
  write_file(dir / "scene.rib", frame_with("Procedural \"DynamicLoad\" [\"" + (dir / "hair.so").string() +
                                           "\" \"1 2\"] [-1 1 -1 1 -1 1]\n"));
  RunOptions traced;
  traced.environment = "LD_DEBUG=files";
  RunResult r = run_darc(dir.path(), "--trust-rib scene.rib", traced);
  EXPECT_EQ(r.exit_code, kExitOk) << r.err;
  EXPECT_NE(r.err.find("scene.rib:7:1: warning: Procedural: DynamicLoad is not supported: compiled procedurals "
                       "cannot be loaded; skipped"),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("file="), std::string::npos) << "the loader's trace is there: " << r.err;
  EXPECT_EQ(r.err.find("hair.so ["), std::string::npos) << "the library was loaded: " << r.err;
}

TEST(CliProcedural, HelpListsTheTrustFlagAndTheVariable) {
  ScratchDir dir("help");
  RunResult r = run_darc(dir.path(), "--help");
  EXPECT_EQ(r.exit_code, kExitOk);
  EXPECT_NE(r.out.find("--trust-rib"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("DARC_PROCEDURAL_PATH"), std::string::npos) << r.out;
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
