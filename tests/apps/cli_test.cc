// The command-line contract of docs/cli.md: --help, --version, exit codes.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "support/run_command.h"

namespace {

using testsupport::RunCommand;
const std::string kCli = IMPLICITFIT_CLI;

TEST(Cli, HelpListsEveryContractCommand) {
  const auto r = RunCommand(kCli + " --help");
  EXPECT_EQ(r.exit_code, 0);
  for (const char* command : {"fit", "eval", "check", "sample", "batch"})
    EXPECT_NE(r.out.find(command), std::string::npos) << command;
}

TEST(Cli, EverySubcommandHasHelp) {
  for (const char* command : {"fit", "eval", "check", "sample", "batch"}) {
    const auto r = RunCommand(kCli + " " + command + " --help");
    EXPECT_EQ(r.exit_code, 0) << command;
    EXPECT_NE(r.out.find(command), std::string::npos) << command;
  }
}

TEST(Cli, VersionPrintsTheProjectVersion) {
  const auto r = RunCommand(kCli + " --version");
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_NE(r.out.find("implicitfit 0."), std::string::npos) << r.out;
}

TEST(Cli, UnknownCommandsAndMissingArgumentsExit2) {
  EXPECT_EQ(RunCommand(kCli + " frobnicate").exit_code, 2);
  EXPECT_EQ(RunCommand(kCli).exit_code, 2);
  EXPECT_EQ(RunCommand(kCli + " eval").exit_code, 2);
  EXPECT_EQ(RunCommand(kCli + " eval --no-such-option a b").exit_code, 2);
}

}  // namespace

namespace {

// The messages of docs/cli.md "Messages": the word at fault is named first, with the nearest
// known name, on one line.
TEST(CliMessages, UnknownOptionIsNamedBeforeAMissingRequiredOne) {
  const auto r = RunCommand(kCli + " fit " IMPLICITFIT_SOURCE_DIR
                                   "/datasets/data/cgal_sphere_single.xyz --modle sphere");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("implicitfit fit: unknown option --modle (did you mean --model?)"),
            std::string::npos)
      << r.err;
  EXPECT_EQ(r.err.find("is required"), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
}

TEST(CliMessages, UnknownOptionFarFromEveryNameHasNoSuggestion) {
  const auto r = RunCommand(kCli + " eval --zzzzzzzzzzzz a.json b.xyz");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("implicitfit eval: unknown option --zzzzzzzzzzzz;"), std::string::npos)
      << r.err;
  EXPECT_EQ(r.err.find("did you mean"), std::string::npos) << r.err;
}

TEST(CliMessages, UnknownCommandSuggestsTheNearestAndListsThemAll) {
  const auto r = RunCommand(kCli + " fitt cloud.xyz");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("implicitfit: unknown command 'fitt' (did you mean 'fit'?)"),
            std::string::npos)
      << r.err;
  for (const char* command : {"fit", "eval", "check", "sample", "batch", "mesh", "reconstruct",
                              "detect", "design", "verify", "view"})
    EXPECT_NE(r.err.find(command), std::string::npos) << command << ": " << r.err;
}

TEST(CliMessages, MissingRequiredOptionIsOneLineNamingTheCommand) {
  const auto r = RunCommand(kCli + " fit " IMPLICITFIT_SOURCE_DIR
                                   "/datasets/data/cgal_sphere_single.xyz --model sphere");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("implicitfit fit: "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("--out"), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
}

TEST(CliMessages, UnknownModelKindListsEveryKindOfTheFitCommand) {
  const std::string dir = testsupport::ScratchDir("unknown_kind");
  const auto r = RunCommand(kCli +
                            " fit " IMPLICITFIT_SOURCE_DIR
                            "/datasets/data/cgal_sphere_single.xyz --model cylindre --out " +
                            dir + "/m.json");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--model cylindre: unknown kind"), std::string::npos) << r.err;
  // docs/cli.md's command table: every kind `fit --model` takes.
  for (const char* kind :
       {"plane", "sphere", "cylinder", "cone", "torus", "quadric-patch", "cubic-patch", "box",
        "paraboloid", "capsule", "patch-mesh", "partition", "bspline-surface", "bspline-volume"})
    EXPECT_NE(r.err.find(kind), std::string::npos) << kind << ": " << r.err;
  EXPECT_FALSE(testsupport::FileExists(dir + "/m.json"));
}

TEST(CliMessages, NegativeNumbersAndValuesAreNotTakenForOptions) {
  const std::string dir = testsupport::ScratchDir("negative_values");
  testsupport::WriteText(dir + "/s.json", R"({"format": "implicitfit-model", "version": 1,
      "root": {"type": "sphere", "center": [0, 0, 0], "radius": 1}})");
  const auto r = RunCommand(kCli + " mesh " + dir +
                            "/s.json --box -2,-2,-2,2,2,2 --cell 0.25 --out " + dir + "/s.ply");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(testsupport::FileExists(dir + "/s.ply"));
  // A negative value the strict number check refuses is named with its option, not as -n.
  const auto nan = RunCommand(kCli + " sample " + dir + "/s.json --count 10 --noise -nan --out " +
                              dir + "/c.xyz");
  EXPECT_EQ(nan.exit_code, 2);
  EXPECT_NE(nan.err.find("--noise"), std::string::npos) << nan.err;
}

}  // namespace
