// `implicitfit design` (docs/maths.md LP-3), `fit --model partition` (LP-1) and the standard
// deviations of `fit --model box` end to end: exit codes, outputs, refusals without output.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>

#include "support/read_json.h"
#include "support/run_command.h"

namespace {

using nlohmann::json;
using testsupport::FileExists;
using testsupport::RunCommand;
using testsupport::WriteText;
const std::string kCli = IMPLICITFIT_CLI;

using testsupport::ReadJson;

std::string SampleBox(const std::string& name) {
  const std::string dir = testsupport::ScratchDir(name);
  WriteText(dir + "/truth.json", R"({"format": "implicitfit-model", "version": 1, "root":
      {"type": "box", "center": [0.2, 0, 0.1], "axes": [[0.8, 0.6, 0], [-0.6, 0.8, 0]],
       "half_sizes": [0.5, 0.4, 0.3]}})");
  const auto s =
      RunCommand(kCli + " sample " + dir +
                 "/truth.json --count 1500 --noise 0.002 --seed 2 --out " + dir + "/cloud.xyz");
  EXPECT_EQ(s.exit_code, 0) << s.err;
  return dir;
}

TEST(DesignCommand, BuildsAnIntersectionThatFitInitRefines) {
  const std::string dir = SampleBox("design_box");
  const auto d = RunCommand(kCli + " design " + dir +
                            "/cloud.xyz --primitive plane --count 6 --out " + dir + "/design.json");
  ASSERT_EQ(d.exit_code, 0) << d.err;
  const json m = ReadJson(dir + "/design.json")["root"];
  EXPECT_EQ(m["type"], "intersection");
  ASSERT_EQ(m["children"].size(), 7u);
  EXPECT_EQ(m["children"][0]["type"], "ellipsoid");
  EXPECT_EQ(m["children"][1]["type"], "plane");
  const auto f =
      RunCommand(kCli + " fit " + dir + "/cloud.xyz --init " + dir + "/design.json --out " + dir +
                 "/fit.json --report " + dir + "/report.json");
  ASSERT_EQ(f.exit_code, 0) << f.err;
  EXPECT_LT(ReadJson(dir + "/report.json")["rms_distance"].get<double>(), 0.004);
}

TEST(DesignCommand, RefusesBadOptionsWithoutOutput) {
  const std::string dir = SampleBox("design_bad");
  for (const std::string args :
       {"--primitive sphere --count 3", "--count 0", "--count 3 --delta 0.1 --epsilon 0.2"}) {
    const auto d =
        RunCommand(kCli + " design " + dir + "/cloud.xyz " + args + " --out " + dir + "/o.json");
    EXPECT_EQ(d.exit_code, 2) << args;
    EXPECT_FALSE(FileExists(dir + "/o.json")) << args;
  }
}

TEST(PartitionFitCommand, FitsAGridOfPlanesAndReportsDeviations) {
  const std::string dir = SampleBox("partition_box");
  const auto f = RunCommand(kCli + " fit " + dir + "/cloud.xyz --model partition --grid 2x2x1 " +
                            "--out " + dir + "/fit.json --report " + dir + "/report.json");
  ASSERT_EQ(f.exit_code, 0) << f.err;
  const json m = ReadJson(dir + "/fit.json")["root"];
  EXPECT_EQ(m["type"], "partition");
  EXPECT_EQ(m["children"].size(), 4u);
  EXPECT_EQ(m["cuts"][2].size(), 0u);
  const json r = ReadJson(dir + "/report.json");
  EXPECT_TRUE(r["success"].get<bool>());
  EXPECT_GT(r["linear_start_rms"].get<double>(), 0.0);
  const double eps_sd = r["standard_deviations"]["root.epsilon"].get<double>();
  EXPECT_TRUE(std::isfinite(eps_sd) && eps_sd > 0);
}

TEST(PartitionFitCommand, QuadricChildrenFitAnEllipsoidToTheNoise) {
  const std::string dir = testsupport::ScratchDir("partition_quadric");
  WriteText(dir + "/truth.json", R"({"format": "implicitfit-model", "version": 1, "root":
      {"type": "ellipsoid", "center": [0, 0, 0], "radii": [1, 0.7, 0.5],
       "axes": [[1, 0, 0], [0, 1, 0]]}})");
  const auto s =
      RunCommand(kCli + " sample " + dir +
                 "/truth.json --count 3000 --noise 0.002 --seed 3 --out " + dir + "/cloud.xyz");
  ASSERT_EQ(s.exit_code, 0) << s.err;
  const auto f =
      RunCommand(kCli + " fit " + dir + "/cloud.xyz --model partition --grid 2x1x1 " +
                 "--child quadric --out " + dir + "/fit.json --report " + dir + "/report.json");
  ASSERT_EQ(f.exit_code, 0) << f.err;
  EXPECT_EQ(ReadJson(dir + "/fit.json")["root"]["children"][0]["type"], "quadric");
  // Two quadric halves of one ellipsoid: the fit reaches the noise (sigma 0.002).
  EXPECT_LT(ReadJson(dir + "/report.json")["rms_distance"].get<double>(), 0.003);
}

TEST(PartitionFitCommand, QuadricPatchChildrenFitAnEllipsoidToTheNoise) {
  const std::string dir = testsupport::ScratchDir("partition_quadric_patch");
  WriteText(dir + "/truth.json", R"({"format": "implicitfit-model", "version": 1, "root":
      {"type": "ellipsoid", "center": [0, 0, 0], "radii": [1, 0.7, 0.5],
       "axes": [[1, 0, 0], [0, 1, 0]]}})");
  const auto s =
      RunCommand(kCli + " sample " + dir +
                 "/truth.json --count 3000 --noise 0.002 --seed 4 --out " + dir + "/cloud.xyz");
  ASSERT_EQ(s.exit_code, 0) << s.err;
  const auto f = RunCommand(kCli + " fit " + dir +
                            "/cloud.xyz --model partition --grid 2x1x1 --child quadric-patch " +
                            "--out " + dir + "/fit.json --report " + dir + "/report.json");
  ASSERT_EQ(f.exit_code, 0) << f.err;
  const auto model = ReadJson(dir + "/fit.json");
  ASSERT_EQ(model["root"]["children"].size(), 2u);
  for (const auto& child : model["root"]["children"]) {
    EXPECT_EQ(child["type"], "bernstein_patch");
    EXPECT_EQ(child["degree"], 2);
  }
  // Two degree-2 patches (each an exact quadric) of one ellipsoid: the fit reaches the noise.
  EXPECT_LT(ReadJson(dir + "/report.json")["rms_distance"].get<double>(), 0.003);
}

TEST(PartitionFitCommand, RefusesABadGridWithoutOutput) {
  const std::string dir = SampleBox("partition_bad");
  for (const std::string args :
       {"--model partition --grid 3x0x2", "--model partition --grid 3x3", "--model partition",
        "--model partition --grid 2x2x2 --child torus", "--model box --grid 2x2x2"}) {
    const auto f =
        RunCommand(kCli + " fit " + dir + "/cloud.xyz " + args + " --out " + dir + "/o.json");
    EXPECT_EQ(f.exit_code, 2) << args << ": " << f.err;
    EXPECT_FALSE(FileExists(dir + "/o.json")) << args;
  }
}

TEST(ShapeFitCommand, BoxReportGivesAStandardDeviationPerParameter) {
  const std::string dir = SampleBox("box_sd");
  const auto f = RunCommand(kCli + " fit " + dir + "/cloud.xyz --model box --out " + dir +
                            "/fit.json --report " + dir + "/report.json");
  ASSERT_EQ(f.exit_code, 0) << f.err;
  const json r = ReadJson(dir + "/report.json");
  ASSERT_EQ(r["standard_deviations"].size(), r["parameters"].size());
  for (const std::string name : {"root.center[0]", "root.half_sizes[2]"}) {
    const double sd = r["standard_deviations"][name].get<double>();
    // 1500 points, sigma 0.002: a centre coordinate is known to about 0.002 / sqrt(500).
    EXPECT_GT(sd, 1e-6) << name;
    EXPECT_LT(sd, 5e-4) << name;
  }
}

}  // namespace
