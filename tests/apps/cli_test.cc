// The command-line contract of docs/cli.md: --help, --version, exit codes.
#include <gtest/gtest.h>

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
