// The hostile-input battery (issue 26): every case of hostile_case.h run through the command
// line under limits, each a test of its own. For every case: the expected exit code; no crash
// (a signal, a sanitizer report); no hang (the case's wall-clock bound, x4 under the
// sanitizers); bounded memory (peak RSS, under an address-space limit outside the sanitizers);
// the message holding the case's words (the file or option it names); every file the user had
// in the case's folder exactly as before, unless it is a declared output; no temporary left;
// and for exit 2 none of the declared outputs written (all or nothing).
// Under the sanitizers only the cases marked `sanitized` run (a third of them): CI runs the
// whole battery in the plain build and that subset in the sanitized one.
// IMPLICITFIT_BATTERY_CLI=path runs the battery against another build of the tool (e.g. the code
// before the fixes, to see which regression tests fail there).
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <map>
#include <set>

#include "apps/hostile/hostile_case.h"
#include "support/file_snapshot.h"
#include "support/limited_run.h"
#include "support/run_command.h"
#include "support/sanitized_build.h"

namespace hostile {
namespace {

namespace fs = std::filesystem;

constexpr long kMaxRssKb = 1536L * 1024;       // plain builds
constexpr long kMaxRssSanitizedKb = 3072L * 1024;
constexpr long long kAddressSpace = 3LL << 30;  // RLIMIT_AS of every plain run

std::vector<Case> AllCases() {
  std::vector<Case> all;
  for (auto family : {ReaderCases, ModelCases, OptionCases, OutputCases, BatchCases,
                      DegenerateCases}) {
    std::vector<Case> some = family();
    all.insert(all.end(), some.begin(), some.end());
  }
  return all;
}

std::vector<Case> CasesToRun() {
  std::vector<Case> all = AllCases();
  if (!testsupport::kSanitizedBuild) return all;
  std::vector<Case> some;
  for (const Case& c : all)
    if (c.sanitized) some.push_back(c);
  return some;
}

std::string Cli() {
  const char* other = std::getenv("IMPLICITFIT_BATTERY_CLI");
  return other && *other ? other : IMPLICITFIT_CLI;
}

std::string Command(const Case& c) {
  std::string args = c.args;
  if (args.find("{cli}") == std::string::npos) return "exec " + Cli() + " " + args;
  for (size_t at = args.find("{cli}"); at != std::string::npos; at = args.find("{cli}", at))
    args.replace(at, 5, Cli());
  return args;
}

// Is `relative` a declared output (or inside one: "out" covers "out/x.json")?
bool Declared(const Case& c, const std::string& relative) {
  for (const std::string& o : c.outputs)
    if (relative == o || relative.rfind(o + "/", 0) == 0) return true;
  return false;
}

class Battery : public ::testing::TestWithParam<Case> {};

TEST_P(Battery, RefusedCleanly) {
  const Case& c = GetParam();
  const std::string dir = testsupport::ScratchDir("hostile_" + c.name);
  c.setup(dir);
  const auto before = testsupport::SnapshotFolder(dir);

  testsupport::RunLimits limits;
  limits.wall_seconds = c.seconds * (testsupport::kSanitizedBuild ? 4 : 1);
  if (!testsupport::kSanitizedBuild) limits.address_space_bytes = c.address_space ? c.address_space : kAddressSpace;
  const testsupport::LimitedRun run = testsupport::RunLimited(Command(c), dir, limits);
  const std::string context = "case " + c.name + ": " + Command(c) + "\nstderr: " +
                              run.err.substr(0, 2000) + "\nstdout: " + run.out.substr(0, 500);

  EXPECT_FALSE(run.timed_out) << "hang: still running after " << limits.wall_seconds << " s\n"
                              << context;
  EXPECT_EQ(run.signal, 0) << "crash: signal " << run.signal << "\n" << context;
  EXPECT_EQ(run.err.find("AddressSanitizer"), std::string::npos) << context;
  EXPECT_EQ(run.err.find("runtime error:"), std::string::npos) << context;
  EXPECT_EQ(run.err.find("terminate called"), std::string::npos) << context;
  EXPECT_EQ(run.exit_code, c.exit_code) << context;
  EXPECT_LT(run.max_rss_kb, testsupport::kSanitizedBuild ? kMaxRssSanitizedKb : kMaxRssKb)
      << "memory: peak " << run.max_rss_kb / 1024 << " MiB\n" << context;
  for (const std::string& words : c.mention)
    EXPECT_NE(run.err.find(words), std::string::npos) << "the message lacks '" << words << "'\n"
                                                      << context;

  const auto after = testsupport::SnapshotFolder(dir);
  for (const auto& [path, state] : before) {
    if (Declared(c, path)) continue;
    const auto it = after.find(path);
    if (it == after.end()) {
      ADD_FAILURE() << "user file " << path << " was removed\n" << context;
      continue;
    }
    EXPECT_TRUE(it->second == state) << "user file " << path << " changed: was "
                                     << state.Describe() << ", now " << it->second.Describe()
                                     << "\n" << context;
  }
  for (const auto& [path, state] : after) {
    if (before.count(path)) continue;  // the user's own (a live run's temporary included)
    EXPECT_EQ(path.find(".implicitfit-"), std::string::npos) << "temporary left: " << path << "\n"
                                                             << context;
    EXPECT_TRUE(Declared(c, path)) << "undeclared file written: " << path << "\n" << context;
    if (c.exit_code == 2 && run.exit_code == 2 && c.args.find("{cli}") == std::string::npos)
      ADD_FAILURE() << "exit 2 but output " << path << " written (all or nothing)\n" << context;
  }
  for (const std::string& path : c.must_exist)
    EXPECT_TRUE(after.count(path)) << path << " missing\n" << context;
  if (c.check)
    for (const std::string& problem : c.check(dir, RunOutcome{run.exit_code, run.out, run.err}))
      ADD_FAILURE() << problem << "\n" << context;
  if (!HasFailure()) fs::remove_all(dir);
}

std::string CaseName(const ::testing::TestParamInfo<Case>& info) { return info.param.name; }

INSTANTIATE_TEST_SUITE_P(Hostile, Battery, ::testing::ValuesIn(CasesToRun()), CaseName);

// The battery's own contract: enough cases, unique names, every family present.
TEST(BatteryContract, AtLeast300CasesWithUniqueNames) {
  const std::vector<Case> all = AllCases();
  EXPECT_GE(all.size(), 300u);
  std::set<std::string> names;
  std::map<std::string, int> families;
  for (const Case& c : all) {
    EXPECT_TRUE(names.insert(c.name).second) << "duplicate case name " << c.name;
    ++families[c.family];
  }
  for (const char* f : {"readers", "models", "options", "outputs", "batch", "degenerate"})
    EXPECT_GT(families[f], 0) << f;
  size_t sanitized = 0;
  for (const Case& c : all) sanitized += c.sanitized;
  std::printf("battery: %zu cases (", all.size());
  for (const auto& [f, n] : families) std::printf(" %s %d", f.c_str(), n);
  std::printf(" ), %zu in the sanitized subset\n", sanitized);
}

// The regression tests of issue 26's defects: every defect has cases (printed for the record).
TEST(BatteryContract, EveryDefectHasARegressionCase) {
  std::map<std::string, std::vector<std::string>> by_defect;
  for (const Case& c : AllCases())
    if (!c.defect.empty()) by_defect[c.defect].push_back(c.name);
  EXPECT_GE(by_defect.size(), 25u);
  for (const auto& [defect, names] : by_defect) {
    std::string list;
    for (const std::string& n : names) list += " " + n;
    std::printf("defect: %s:%s\n", defect.c_str(), list.c_str());
  }
}

}  // namespace
}  // namespace hostile
