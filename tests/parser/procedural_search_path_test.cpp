// The procedural search path a RIB sets may only narrow the user's folders (--procedural-path,
// DARC_PROCEDURAL_PATH): a folder outside them, reached by an absolute name, by ".." or through a
// symbolic link, is dropped with a warning at the Option that names it, and nothing in it runs.
// With --trust-rib the RIB's folders are kept, each widening one reported once.
#include <gtest/gtest.h>

#include "procedural_test_util.h"

namespace darc::test {
namespace {

// Option "searchpath" "procedural" [path], then RunProgram of `program` (its first word).
std::string search_then_run(const std::string& path, const std::string& program) {
  return "Option \"searchpath\" \"procedural\" [\"" + path + "\"]\nProcedural \"RunProgram\" [\"" + program +
         "\" \"\"] [0 1 0 1 0 1]\n";
}

std::function<void(RibParser&)> user_folders(const std::vector<std::string>& dirs, bool trust_rib = false) {
  return [dirs, trust_rib](RibParser& p) {
    p.set_procedural_folders(dirs);
    p.set_trust_rib(trust_rib);
  };
}

// The issue as reported: a scene names /usr/bin and runs touch. Nothing runs, with or without
// folders of the user's.
TEST(ProceduralSearchPath, ASceneCannotAddASystemFolder) {
  ScratchFolder dir;
  fs::create_directories(dir / "allowed");
  const std::string victim = (dir / "touched").string();
  for (const std::vector<std::string>& allowed : {std::vector<std::string>{}, {(dir / "allowed").string()}}) {
    SCOPED_TRACE(allowed.empty() ? "no user folder" : "a user folder");
    auto r = parse_procedural(search_then_run("/usr/bin:/bin:@", "touch " + victim), "scene.rib",
                              user_folders(allowed));
    EXPECT_FALSE(fs::exists(victim)) << "touch ran";
    const auto warnings = r->warnings();
    ASSERT_EQ(warnings.size(), 2u);
    EXPECT_EQ(warnings[0].loc.str(), "scene.rib:1:1");
    EXPECT_EQ(warnings[0].request, "Option");
    EXPECT_TRUE(contains(warnings[0].message, "procedural folder \"/usr/bin\" dropped from the search path: "))
        << warnings[0].message;
    EXPECT_TRUE(contains(warnings[0].message, "is not inside the folders you allowed")) << warnings[0].message;
    EXPECT_TRUE(contains(warnings[0].message, "allow it with --procedural-path")) << warnings[0].message;
    EXPECT_TRUE(contains(warnings[1].message, "/bin")) << warnings[1].message;
    const auto errors = r->errors();
    ASSERT_EQ(errors.size(), 1u);
    EXPECT_EQ(errors[0].loc.str(), "scene.rib:2:1");
    EXPECT_TRUE(contains(errors[0].message, allowed.empty() ? "RunProgram: program \"touch\" refused: no folder is allowed"
                                                            : "RunProgram: program \"touch\" is not in the"))
        << errors[0].message;
  }
}

TEST(ProceduralSearchPath, DotDotAndLinksCannotLeaveTheUserFolders) {
  ScratchFolder dir;
  dir.write_program("outside/gen.sh", "touch '" + (dir / "started").string() + "'\nprintf '\\377'\n");
  fs::create_directories(dir / "allowed");
  fs::create_directory_symlink(dir / "outside", dir / "allowed/link");
  for (const std::string& path : {(dir / "allowed/../outside").string(), (dir / "allowed/link").string()}) {
    SCOPED_TRACE(path);
    auto r = parse_procedural(search_then_run(path, "gen.sh"), "scene.rib",
                              user_folders({(dir / "allowed").string()}));
    ASSERT_EQ(r->warnings().size(), 1u);
    const std::string real = fs::canonical(dir / "outside").string();
    EXPECT_TRUE(contains(r->warnings()[0].message, std::string("(").append(real).append(")")))
        << "the warning names where the folder really is: " << r->warnings()[0].message;
    ASSERT_EQ(r->errors().size(), 1u);
    EXPECT_TRUE(contains(r->errors()[0].message, "the scene's procedural search path kept no folder"))
        << r->errors()[0].message;
    EXPECT_FALSE(fs::exists(dir / "started"));
  }
}

// Narrowing replaces the path: a program in the user's folder but not in the narrowed part is not
// found, one in the narrowed part is.
TEST(ProceduralSearchPath, AFolderInsideTheUserFoldersNarrowsThePath) {
  ScratchFolder dir;
  dir.write_program("allowed/top.sh", "printf 'Sides 1\\n\\377'\n");
  dir.write_program("allowed/sub/inner.sh", "printf 'Sides 2\\n\\377'\n");
  auto r = parse_procedural(search_then_run((dir / "allowed/sub").string(), "inner.sh") +
                                "Procedural \"RunProgram\" [\"top.sh\" \"\"] [0 1 0 1 0 1]\n",
                            "scene.rib", user_folders({(dir / "allowed").string()}));
  EXPECT_TRUE(r->warnings().empty()) << r->warnings()[0].str();
  const auto sides = r->target.named("Sides");
  ASSERT_EQ(sides.size(), 1u);
  EXPECT_EQ(sides[0].numbers[0], 2);
  ASSERT_EQ(r->errors().size(), 1u);
  EXPECT_TRUE(contains(r->errors()[0].message, "program \"top.sh\" is not in the procedural search path"))
      << r->errors()[0].message;
}

TEST(ProceduralSearchPath, AMissingFolderIsDropped) {
  ScratchFolder dir;
  fs::create_directories(dir / "allowed");
  auto r = parse_procedural(search_then_run((dir / "allowed/none").string(), "gen.sh"), "scene.rib",
                            user_folders({(dir / "allowed").string()}));
  ASSERT_EQ(r->warnings().size(), 1u);
  EXPECT_TRUE(contains(r->warnings()[0].message, "dropped from the search path: it does not exist"))
      << r->warnings()[0].message;
}

// --trust-rib: the RIB's folder is kept, once reported, and its program runs.
TEST(ProceduralSearchPath, TrustingTheRibKeepsAWideningFolderWithAWarning) {
  ScratchFolder dir;
  dir.write_program("outside/gen.sh", "printf 'Sides 2\\n\\377'\n");
  const std::string rib = search_then_run((dir / "outside").string(), "gen.sh");
  auto r = parse_procedural(rib + rib, "scene.rib", user_folders({}, true));
  EXPECT_TRUE(r->ok) << r->first_error();
  EXPECT_EQ(r->target.named("Sides").size(), 2u);
  const auto warnings = r->warnings();
  ASSERT_EQ(warnings.size(), 1u) << "one warning per widening folder";
  EXPECT_EQ(warnings[0].loc.str(), "scene.rib:1:1");
  EXPECT_TRUE(contains(warnings[0].message, "trusting the procedural folder \"" + (dir / "outside").string() +
                                                "\" that the RIB chose (--trust-rib)"))
      << warnings[0].message;
}

}  // namespace
}  // namespace darc::test
