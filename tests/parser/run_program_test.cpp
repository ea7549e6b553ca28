// Procedural "RunProgram": which programs may run (only from the user's folders, or the part of
// them the RIB's procedural search path keeps; no way out by '..' or symbolic links; --trust-rib
// widens, with a warning), the exchange with the program
// (request line, answer up to \377), and every way it can fail as an error at the request's
// position: a time limit, an exit status, a signal, bad RIB, a missing terminator, too much output.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <fstream>

#include "parser/program_search.h"
#include "procedural_test_util.h"

namespace darc::test {
namespace {

// A program that answers with one Sphere and records that it ran.
std::string sphere_program(const ScratchFolder& dir) {
  return "touch '" + (dir / "started").string() + "'\nprintf 'Sphere 1 -1 1 360\\n\\377'\n";
}

std::function<void(RibParser&)> folders(const std::vector<std::string>& dirs) {
  return [dirs](RibParser& p) { p.set_procedural_folders(dirs); };
}

std::function<void(RibParser&)> folder_and_limits(const std::string& dir, RunProgramLimits limits) {
  return [dir, limits](RibParser& p) {
    p.set_procedural_folders({dir});
    p.set_run_program_limits(limits);
  };
}

TEST(RunProgram, AProgramOnTheSearchPathAnswersWithRib) {
  ScratchFolder dir;
  dir.write_program("bin/gen.sh", "read detail data\nprintf 'Sphere %s -1 1 360\\n\\377' \"$data\"\n");
  // The user allows the scratch folder; the scene narrows the path to its bin.
  auto r = parse_procedural("Option \"searchpath\" \"procedural\" [\"" + (dir / "bin").string() +
                                "\"]\nWorldBegin\nProcedural \"RunProgram\" [\"gen.sh\" \"2.5\"] [-3 3 -3 3 -3 3]\n"
                                "WorldEnd\n",
                            (dir / "scene.rib").string(), folders({dir.str()}));
  EXPECT_TRUE(r->warnings().empty()) << r->warnings()[0].str();
  EXPECT_TRUE(r->ok) << r->first_error();
  const auto spheres = r->target.named("Sphere");
  ASSERT_EQ(spheres.size(), 1u);
  EXPECT_EQ(spheres[0].numbers[0], 2.5) << "the data reached the program";
  // Positions in the answer name the program.
  EXPECT_EQ(spheres[0].loc.str(), "RunProgram \"gen.sh\" (output):1:1");
  EXPECT_EQ(r->target.named("AttributeBegin").size(), 1u);
  EXPECT_EQ(r->target.named("AttributeEnd").size(), 1u);
}

TEST(RunProgram, TheProgramStringIsSplitIntoArgumentsOnWhiteSpace) {
  ScratchFolder dir;
  dir.write_program("args.sh", "printf 'ArchiveRecord \"comment\" \"%s|%s|%s\"\\n\\377' \"$1\" \"$2\" \"$#\"\n");
  auto r = parse_procedural("Procedural \"RunProgram\" [\"args.sh  -n 12 \" \"\"] [0 1 0 1 0 1]\n", "scene.rib",
                            folders({dir.str()}));
  EXPECT_TRUE(r->ok) << r->first_error();
  const auto records = r->target.named("ArchiveRecord");
  ASSERT_EQ(records.size(), 1u);
  EXPECT_EQ(records[0].strings[1], "-n|12|2");
}

TEST(RunProgram, WithoutASearchPathNothingRuns) {
  ScratchFolder dir;
  dir.write_program("gen.sh", sphere_program(dir));
  auto r = parse_procedural(
      "WorldBegin\nProcedural \"RunProgram\" [\"" + (dir / "gen.sh").string() + "\" \"\"] [0 1 0 1 0 1]\nWorldEnd\n",
      "scene.rib");
  const auto errors = r->errors();
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_TRUE(contains(errors[0].message,
                       "refused: no folder is allowed to hold procedural programs; allow the generator's folder "
                       "with --procedural-path DIR or in DARC_PROCEDURAL_PATH"))
      << errors[0].message;
  EXPECT_EQ(errors[0].loc.str(), "scene.rib:2:1");
  EXPECT_FALSE(fs::exists(dir / "started"));
  EXPECT_TRUE(r->target.named("Sphere").empty());
}

TEST(RunProgram, AnAbsolutePathOutsideTheFoldersIsRefused) {
  ScratchFolder dir;
  dir.write_program("trusted/ok.sh", "printf '\\377'\n");
  dir.write_program("elsewhere/gen.sh", sphere_program(dir));
  auto r = parse_procedural("Procedural \"RunProgram\" [\"" + (dir / "elsewhere/gen.sh").string() +
                                "\" \"\"] [0 1 0 1 0 1]\nProcedural \"RunProgram\" [\"/bin/sh -c true\" \"\"] "
                                "[0 1 0 1 0 1]\n",
                            "scene.rib", folders({(dir / "trusted").string()}));
  const auto errors = r->errors();
  ASSERT_EQ(errors.size(), 2u);
  EXPECT_TRUE(contains(errors[0].message, "outside the procedural search path")) << errors[0].message;
  EXPECT_TRUE(contains(errors[1].message, "outside the procedural search path")) << errors[1].message;
  EXPECT_EQ(errors[1].loc.line, 2);
  EXPECT_FALSE(fs::exists(dir / "started"));
}

TEST(RunProgram, DotDotCannotLeaveTheFolders) {
  ScratchFolder dir;
  dir.write_program("gen.sh", sphere_program(dir));
  dir.write_program("trusted/sub/ok.sh", "printf 'Sides 1\\n\\377'\n");
  auto r = parse_procedural(
      "Procedural \"RunProgram\" [\"../gen.sh\" \"\"] [0 1 0 1 0 1]\n"
      "Procedural \"RunProgram\" [\"sub/../../gen.sh\" \"\"] [0 1 0 1 0 1]\n"
      "Procedural \"RunProgram\" [\"sub/ok.sh\" \"\"] [0 1 0 1 0 1]\n",
      "scene.rib", folders({(dir / "trusted").string()}));
  const auto errors = r->errors();
  ASSERT_EQ(errors.size(), 2u) << r->first_error();
  EXPECT_TRUE(contains(errors[0].message, "resolves to " + fs::canonical(dir / "gen.sh").string()))
      << errors[0].message;
  EXPECT_TRUE(contains(errors[1].message, "outside the procedural search path")) << errors[1].message;
  EXPECT_FALSE(fs::exists(dir / "started"));
  // A name with '/' that stays inside is fine.
  EXPECT_EQ(r->target.named("Sides").size(), 1u);
}

TEST(RunProgram, ASymbolicLinkCannotLeaveTheFolders) {
  ScratchFolder dir;
  dir.write_program("outside/gen.sh", sphere_program(dir));
  fs::create_directories(dir / "trusted");
  fs::create_symlink(dir / "outside/gen.sh", dir / "trusted/gen.sh");
  fs::create_directory_symlink(dir / "outside", dir / "trusted/linked");
  auto r = parse_procedural(
      "Procedural \"RunProgram\" [\"gen.sh\" \"\"] [0 1 0 1 0 1]\n"
      "Procedural \"RunProgram\" [\"linked/gen.sh\" \"\"] [0 1 0 1 0 1]\n",
      "scene.rib", folders({(dir / "trusted").string()}));
  const auto errors = r->errors();
  ASSERT_EQ(errors.size(), 2u);
  for (const Diagnostic& e : errors)
    EXPECT_TRUE(contains(e.message, "outside the procedural search path")) << e.message;
  EXPECT_FALSE(fs::exists(dir / "started"));
}

TEST(RunProgram, AFileThatIsNotExecutableIsAnError) {
  ScratchFolder dir;
  dir.write("gen.sh", "#!/bin/sh\nprintf '\\377'\n");
  auto r = parse_procedural("Procedural \"RunProgram\" [\"gen.sh\" \"\"] [0 1 0 1 0 1]\n", "scene.rib",
                            folders({dir.str()}));
  ASSERT_EQ(r->errors().size(), 1u);
  EXPECT_TRUE(contains(r->errors()[0].message, "is not executable")) << r->errors()[0].message;
}

TEST(ProgramSearch, FoldersAreSearchedInOrder) {
  ScratchFolder dir;
  dir.write_program("a/gen.sh", "");
  dir.write_program("b/gen.sh", "");
  dir.write_program("b/only_b.sh", "");
  const std::vector<std::string> path = {(dir / "missing").string(), (dir / "a").string(), (dir / "b").string()};
  EXPECT_EQ(find_program("gen.sh", path).path, fs::canonical(dir / "a/gen.sh").string());
  EXPECT_EQ(find_program("only_b.sh", path).path, fs::canonical(dir / "b/only_b.sh").string());
  const ProgramSearch none = find_program("nowhere.sh", path);
  EXPECT_TRUE(none.path.empty());
  EXPECT_TRUE(contains(none.error, "is not in the procedural search path")) << none.error;
}

TEST(RunProgram, TheSearchPathTakesAmpersandAtAndRelativeFolders) {
  ScratchFolder dir;
  dir.write_program("cli/from_cli.sh", "printf 'Sides 1\\n\\377'\n");
  dir.write_program("lib/scene/bin/beside.sh", "printf 'Sides 2\\n\\377'\n");
  dir.write_program("lib/abs/absolute.sh", "printf 'Sides 3\\n\\377'\n");
  // The user allows cli and lib. "bin" is relative to the scene file; "&" keeps the previous path
  // (lib/abs, found by nothing else); "@" is the user's folders.
  auto r = parse_procedural("Option \"searchpath\" \"procedural\" [\"" + (dir / "lib/abs").string() +
                                "\"]\n"
                                "Option \"searchpath\" \"procedural\" [\"bin:&:@\"]\n"
                                "Procedural \"RunProgram\" [\"from_cli.sh\" \"\"] [0 1 0 1 0 1]\n"
                                "Procedural \"RunProgram\" [\"beside.sh\" \"\"] [0 1 0 1 0 1]\n"
                                "Procedural \"RunProgram\" [\"absolute.sh\" \"\"] [0 1 0 1 0 1]\n",
                            (dir / "lib/scene/main.rib").string(), [&](RibParser& p) {
                              p.set_procedural_folders({(dir / "cli").string(), (dir / "lib").string()});
                              ASSERT_EQ(p.procedural_search_path().size(), 2u) << "the user's, until the RIB sets one";
                            });
  EXPECT_TRUE(r->ok) << r->first_error();
  EXPECT_TRUE(r->warnings().empty()) << r->warnings()[0].str();
  const auto sides = r->target.named("Sides");
  ASSERT_EQ(sides.size(), 3u);
  EXPECT_EQ(sides[0].numbers[0], 1);
  EXPECT_EQ(sides[1].numbers[0], 2);
  EXPECT_EQ(sides[2].numbers[0], 3);
}

TEST(RunProgram, AProgramPastTheTimeLimitIsKilledAndIsAnError) {
  ScratchFolder dir;
  dir.write_program("slow.sh", "sleep 30\nprintf 'Sphere 1 -1 1 360\\n\\377'\n");
  RunProgramLimits limits;
  limits.time_limit = std::chrono::milliseconds(200);
  auto r = parse_procedural("Sides 1\n  Procedural \"RunProgram\" [\"slow.sh\" \"\"] [0 1 0 1 0 1]\nSides 2\n",
                            "scene.rib", folder_and_limits(dir.str(), limits));
  const auto errors = r->errors();
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_EQ(errors[0].message, "RunProgram \"slow.sh\": did not answer within 0.2 s: killed");
  EXPECT_EQ(errors[0].loc.str(), "scene.rib:2:3");
  EXPECT_EQ(r->target.named("Sides").size(), 2u);
  EXPECT_TRUE(r->target.named("Sphere").empty());
}

// Whether process `pid` has ended (gone, or a zombie nobody has waited for yet).
bool process_ended(pid_t pid) {
  std::ifstream stat("/proc/" + std::to_string(pid) + "/stat");
  std::string fields;
  if (!std::getline(stat, fields)) return true;
  const size_t paren = fields.rfind(')');
  return paren != std::string::npos && paren + 2 < fields.size() && fields[paren + 2] == 'Z';
}

TEST(RunProgram, TheTimeLimitAlsoKillsWhatTheProgramStarted) {
  ScratchFolder dir;
  const std::string pid_file = (dir / "sleep.pid").string();
  dir.write_program("starts.sh", "sleep 30 &\necho $! > '" + pid_file + "'\nwait\n");
  RunProgramLimits limits;
  limits.time_limit = std::chrono::milliseconds(1000);
  auto r = parse_procedural("Procedural \"RunProgram\" [\"starts.sh\" \"\"] [0 1 0 1 0 1]\n", "scene.rib",
                            folder_and_limits(dir.str(), limits));
  ASSERT_EQ(r->errors().size(), 1u);
  std::ifstream in(pid_file);
  pid_t sleeper = 0;
  ASSERT_TRUE(in >> sleeper) << "the script did not get to start its sleep";
  // SIGKILL went to the whole process group; its delivery is asynchronous, so allow it a while.
  for (int i = 0; i < 1000 && !process_ended(sleeper); ++i) ::usleep(10'000);
  EXPECT_TRUE(process_ended(sleeper)) << "the sleep started by the program outlived it";
}

TEST(RunProgram, AProgramThatAnswersButDoesNotExitIsKilledAtTheTimeLimit) {
  ScratchFolder dir;
  dir.write_program("stays.sh", "printf 'Sides 1\\n\\377'\nexec sleep 30\n");
  RunProgramLimits limits;
  limits.time_limit = std::chrono::milliseconds(200);
  auto r = parse_procedural("Procedural \"RunProgram\" [\"stays.sh\" \"\"] [0 1 0 1 0 1]\n", "scene.rib",
                            folder_and_limits(dir.str(), limits));
  ASSERT_EQ(r->errors().size(), 1u);
  EXPECT_EQ(r->errors()[0].message,
            "RunProgram \"stays.sh\": answered but did not exit within 0.2 s after its input was closed: killed");
  EXPECT_TRUE(r->target.named("Sides").empty()) << "a failed request adds nothing";
}

TEST(RunProgram, ANonZeroExitOrASignalIsAnError) {
  ScratchFolder dir;
  dir.write_program("fails.sh", "printf 'Sphere 1 -1 1 360\\n\\377'\nexit 3\n");
  dir.write_program("crashes.sh", "kill -9 $$\n");
  auto r = parse_procedural(
      "Procedural \"RunProgram\" [\"fails.sh\" \"\"] [0 1 0 1 0 1]\n"
      "Procedural \"RunProgram\" [\"crashes.sh\" \"\"] [0 1 0 1 0 1]\n",
      "scene.rib", folders({dir.str()}));
  const auto errors = r->errors();
  ASSERT_EQ(errors.size(), 2u);
  EXPECT_EQ(errors[0].message, "RunProgram \"fails.sh\": exited with status 3");
  EXPECT_EQ(errors[0].loc.line, 1);
  EXPECT_TRUE(contains(errors[1].message, "RunProgram \"crashes.sh\": was killed by signal 9")) << errors[1].message;
  EXPECT_EQ(errors[1].loc.line, 2);
  EXPECT_TRUE(r->target.named("Sphere").empty());
}

TEST(RunProgram, BadRibInTheAnswerIsAnErrorAtItsPositionInTheOutput) {
  ScratchFolder dir;
  dir.write_program("bad.sh", "printf 'Sides 1\\nSphere 1 \"x\" 1 360\\nSides 2\\n\\377'\n");
  auto r = parse_procedural("Procedural \"RunProgram\" [\"bad.sh\" \"\"] [0 1 0 1 0 1]\n", "scene.rib",
                            folders({dir.str()}));
  const auto errors = r->errors();
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_EQ(errors[0].loc.str(), "RunProgram \"bad.sh\" (output):2:10");
  EXPECT_EQ(errors[0].request, "Sphere");
  // The rest of the answer is read, as in a file.
  EXPECT_EQ(r->target.named("Sides").size(), 2u);
}

TEST(RunProgram, AnAnswerWithoutTheTerminatorIsAnError) {
  ScratchFolder dir;
  dir.write_program("unended.sh", "printf 'Sphere 1 -1 1 360\\n'\n");
  auto r = parse_procedural("Procedural \"RunProgram\" [\"unended.sh\" \"\"] [0 1 0 1 0 1]\n", "scene.rib",
                            folders({dir.str()}));
  ASSERT_EQ(r->errors().size(), 1u);
  EXPECT_EQ(r->errors()[0].message,
            "RunProgram \"unended.sh\": ended without the \\377 terminator after 18 bytes of output");
  EXPECT_TRUE(r->target.named("Sphere").empty());
}

TEST(RunProgram, AnAnswerOverTheSizeLimitIsAnError) {
  ScratchFolder dir;
  dir.write_program("chatty.sh", "while true; do printf 'Sides 1\\n'; done\n");
  RunProgramLimits limits;
  limits.max_output_bytes = 4096;
  auto r = parse_procedural("Procedural \"RunProgram\" [\"chatty.sh\" \"\"] [0 1 0 1 0 1]\n", "scene.rib",
                            folder_and_limits(dir.str(), limits));
  ASSERT_EQ(r->errors().size(), 1u);
  EXPECT_EQ(r->errors()[0].message, "RunProgram \"chatty.sh\": wrote more than 4096 bytes of RIB: killed");
  EXPECT_TRUE(r->target.named("Sides").empty());
}

// A program that never reads its input gets a request larger than a pipe holds: darc must not
// die of SIGPIPE nor wait on the write.
TEST(RunProgram, AProgramThatIgnoresItsInputStillAnswers) {
  ScratchFolder dir;
  dir.write_program("deaf.sh", "exec 0<&-\nprintf 'Sides 1\\n\\377'\n");
  const std::string data(1 << 20, 'x');
  auto r = parse_procedural("Procedural \"RunProgram\" [\"deaf.sh\" \"" + data + "\"] [0 1 0 1 0 1]\n", "scene.rib",
                            folders({dir.str()}));
  EXPECT_TRUE(r->ok) << r->first_error();
  EXPECT_EQ(r->target.named("Sides").size(), 1u);
}

// A generator whose answer calls it again ends at the nesting limit, with an error.
TEST(RunProgram, RecursionEndsAtTheNestingLimit) {
  ScratchFolder dir;
  dir.write_program("self.sh", "printf 'Procedural \"RunProgram\" [\"self.sh\" \"\"] [0 1 0 1 0 1]\\n\\377'\n");
  auto r = parse_procedural("Procedural \"RunProgram\" [\"self.sh\" \"\"] [0 1 0 1 0 1]\n", "scene.rib",
                            folders({dir.str()}));
  ASSERT_EQ(r->errors().size(), 1u);
  EXPECT_EQ(r->errors()[0].message, "RunProgram \"self.sh\": procedurals nested deeper than 64 levels");
  EXPECT_EQ(r->errors()[0].loc.file_name(), "RunProgram \"self.sh\" (output)");
  EXPECT_EQ(r->target.named("AttributeBegin").size(), 63u);
  EXPECT_EQ(r->target.named("AttributeEnd").size(), 63u);
}

// The example generator (scenes/procedural/grass.py), as grass.rib uses it.
TEST(RunProgram, TheGrassGeneratorWritesTheBladesAskedFor) {
  const std::string scenes = std::string(DARC_SOURCE_DIR) + "/scenes/procedural";
  const std::string rib = "Option \"searchpath\" \"procedural\" [\"" + scenes +
                          "\"]\nProcedural \"RunProgram\" [\"grass.py\" \"25 7\"] [-1.3 1.3 0 0.5 -1.3 1.3]\n"
                          "Procedural \"RunProgram\" [\"grass.py\" \"25 7\"] [-1.3 1.3 0 0.5 -1.3 1.3]\n";
  auto r = parse_procedural(rib, "scene.rib", folders({scenes}));
  EXPECT_TRUE(r->ok) << r->first_error();
  const auto curves = r->target.named("Curves");
  ASSERT_EQ(curves.size(), 2u);
  EXPECT_EQ(curves[0].strings, (std::vector<std::string>{"cubic", "nonperiodic"}));
  EXPECT_EQ(curves[0].numbers, std::vector<double>(25, 4.0));
  const Param* P = curves[0].params.find("P");
  ASSERT_NE(P, nullptr);
  ASSERT_EQ(P->floats.size(), 25u * 4 * 3);
  // Inside the bound the RIB gives (x, z in [-1.3, 1.3], y in [0, 0.5]).
  for (size_t i = 0; i < P->floats.size(); i += 3) {
    EXPECT_LE(std::abs(P->floats[i]), 1.3f);
    EXPECT_GE(P->floats[i + 1], 0.0f);
    EXPECT_LE(P->floats[i + 1], 0.5f);
    EXPECT_LE(std::abs(P->floats[i + 2]), 1.3f);
  }
  ASSERT_NE(curves[0].params.find("width"), nullptr);
  EXPECT_EQ(curves[0].params.find("width")->floats.size(), 25u * 2);
  ASSERT_NE(curves[0].params.find("Cs"), nullptr);
  EXPECT_EQ(curves[0].params.find("Cs")->decl.storage, StorageClass::Uniform);
  // The same data gives the same blades.
  EXPECT_TRUE(curves[0].same_as(curves[1]));
}

}  // namespace
}  // namespace darc::test
