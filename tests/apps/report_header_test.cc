// The header of every JSON report (apps/report_header.h, docs/cli.md "Reports"): the format,
// its version, the job, the tool's version, the input (path, points, normals), the settings
// given or defaulted, the seed and the units. Expected values come from the command lines and
// the files themselves (the point count is the file's line count), not from the tool.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "support/run_command.h"

namespace {

using nlohmann::json;
using testsupport::RunCommand;
const std::string kCli = IMPLICITFIT_CLI;
const std::string kData = std::string(IMPLICITFIT_SOURCE_DIR) + "/datasets/data/";

size_t LineCount(const std::string& path) {
  std::ifstream in(path);
  size_t n = 0;
  for (std::string line; std::getline(in, line);) n += !line.empty();
  return n;
}

std::string ToolVersion() {
  const std::string out = RunCommand(kCli + " --version").out;  // "implicitfit 0.1.0"
  return out.substr(out.find(' ') + 1, out.find_first_of("\n") - out.find(' ') - 1);
}

void ExpectHeader(const json& report, const std::string& job, const std::string& input,
                  size_t points) {
  EXPECT_EQ(report.value("format", ""), "implicitfit-report");
  EXPECT_EQ(report.value("format_version", 0), 1);
  EXPECT_EQ(report.value("job", ""), job);
  EXPECT_EQ(report.value("tool_version", ""), ToolVersion());
  ASSERT_TRUE(report.contains("input")) << report.dump();
  EXPECT_EQ(report["input"].value("path", ""), input);
  if (points > 0) EXPECT_EQ(report["input"].value("points", size_t{0}), points);
  EXPECT_TRUE(report["input"].contains("normals"));
  ASSERT_TRUE(report.contains("settings") && report["settings"].is_object());
  EXPECT_EQ(report["units"], json({{"length", "input"}, {"angle", "degree"}}));
}

TEST(ReportHeader, FitReportNamesItsInputSettingsAndSeed) {
  const std::string dir = testsupport::ScratchDir("header_fit");
  const std::string cloud = kData + "cgal_sphere_single.xyz";
  const auto r = RunCommand(kCli + " fit " + cloud + " --model sphere --seed 7 --threshold 0.01 " +
                            "--out " + dir + "/m.json --report " + dir + "/r.json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json report = json::parse(testsupport::Slurp(dir + "/r.json"));
  ExpectHeader(report, "fit", cloud, LineCount(cloud));
  EXPECT_EQ(report["seed"], 7);
  const json& s = report["settings"];
  EXPECT_EQ(s["model"], "sphere");
  EXPECT_EQ(s["seed"], 7);
  EXPECT_DOUBLE_EQ(s["threshold"].get<double>(), 0.01);
  EXPECT_EQ(s["estimator"], "robust");  // not given: the default
  EXPECT_EQ(s["convex"], false);        // a flag not given
  // Files are not settings: they are the input and the outputs.
  EXPECT_FALSE(s.contains("out"));
  EXPECT_FALSE(s.contains("report"));
  EXPECT_FALSE(s.contains("CLOUD"));
}

TEST(ReportHeader, DetectAndBatchReportsCarryItToo) {
  const std::string dir = testsupport::ScratchDir("header_detect");
  const std::string cloud = kData + "cgal_fin90_two_planes_crease.xyz";
  const auto d = RunCommand(kCli + " detect " + cloud + " --quiet --out " + dir +
                            "/s.json --report " + dir + "/r.json");
  ASSERT_EQ(d.exit_code, 0) << d.err;
  const json report = json::parse(testsupport::Slurp(dir + "/r.json"));
  ExpectHeader(report, "detect", cloud, LineCount(cloud));
  EXPECT_EQ(report["settings"]["seed"], 1);
  const auto b = RunCommand(kCli + " batch " + kData + "cgal_sphere_single.xyz --model sphere " +
                            "--out-dir " + dir);
  ASSERT_EQ(b.exit_code, 0) << b.err;
  const json per_input = json::parse(testsupport::Slurp(dir + "/cgal_sphere_single.report.json"));
  ExpectHeader(per_input, "batch", kData + "cgal_sphere_single.xyz",
               LineCount(kData + "cgal_sphere_single.xyz"));
  EXPECT_EQ(per_input["settings"]["model"], "sphere");
}

TEST(ReportHeader, CheckJsonOnStandardOutput) {
  const std::string dir = testsupport::ScratchDir("header_check");
  testsupport::WriteText(dir + "/s.json", R"({"format": "implicitfit-model", "version": 1,
      "root": {"type": "sphere", "center": [0, 0, 0], "radius": 1}})");
  const auto r = RunCommand(kCli + " check --json " + dir + "/s.json");
  const json report = json::parse(r.out);
  ExpectHeader(report, "check", dir + "/s.json", 0);
}

}  // namespace
