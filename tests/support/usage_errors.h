// Usage errors of a command end to end: each case's arguments make `command` exit 2 with the
// case's message in stderr, and leave no `output` file behind.
#pragma once

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "support/run_command.h"

namespace testsupport {

struct UsageErrorCase {
  std::string args, message;
};

inline void ExpectUsageErrors(const std::string& command, const std::vector<UsageErrorCase>& cases,
                              const std::string& output) {
  for (const UsageErrorCase& c : cases) {
    const CommandResult r = RunCommand(command + " " + c.args);
    EXPECT_EQ(r.exit_code, 2) << c.args;
    EXPECT_NE(r.err.find(c.message), std::string::npos) << c.args << ": " << r.err;
    EXPECT_FALSE(FileExists(output)) << c.args;
  }
}

}  // namespace testsupport
