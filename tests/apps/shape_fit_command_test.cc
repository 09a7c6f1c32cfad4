// `implicitfit sample` and `implicitfit fit --model box | paraboloid | capsule` end to end on the
// issue-16 kinds: clouds sampled from known models (noise, outliers), fitted back from the
// robust starts alone, compared with the models they were sampled from.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <sstream>
#include <vector>

#include "support/model_document.h"
#include "support/read_json.h"
#include "support/run_command.h"

namespace {

using nlohmann::json;
using testsupport::RunCommand;
using testsupport::WriteText;
const std::string kCli = IMPLICITFIT_CLI;

using testsupport::ReadJson;

std::string SampleAndFit(const std::string& name, const std::string& root,
                         const std::string& kind) {
  const std::string dir = testsupport::ScratchDir(name);
  WriteText(dir + "/truth.json", testsupport::ModelDocument(root));
  const auto s = RunCommand(kCli + " sample " + dir +
                            "/truth.json --count 4000 --noise 0.002 --outliers 0.15 --seed 5" +
                            " --out " + dir + "/cloud.xyz");
  EXPECT_EQ(s.exit_code, 0) << s.err;
  const auto r = RunCommand(kCli + " fit " + dir + "/cloud.xyz --model " + kind + " --out " + dir +
                            "/fit.json --report " + dir + "/report.json");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  return dir;
}

TEST(ShapeFitCommand, BoxFromARobustStart) {
  const std::string dir = SampleAndFit("fit_box", R"({"type": "box", "center": [1, -0.5, 0.3],
      "axes": [[0.8, 0.6, 0], [-0.6, 0.8, 0]], "half_sizes": [0.6, 0.4, 0.25]})",
                                       "box");
  const json m = ReadJson(dir + "/fit.json")["root"];
  ASSERT_EQ(m["type"], "box");
  const double c[3] = {1, -0.5, 0.3};
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(m["center"][k].get<double>(), c[k], 2e-3);
  // The fitted axes may be any signed permutation of the true ones: compare sorted half sizes.
  std::vector<double> h = {m["half_sizes"][0], m["half_sizes"][1], m["half_sizes"][2]};
  std::sort(h.begin(), h.end());
  EXPECT_NEAR(h[0], 0.25, 2e-3);
  EXPECT_NEAR(h[1], 0.4, 2e-3);
  EXPECT_NEAR(h[2], 0.6, 2e-3);
  const json report = ReadJson(dir + "/report.json");
  EXPECT_TRUE(report["success"].get<bool>());
  EXPECT_EQ(report["kind"], "box");
  EXPECT_LT(report["rms_distance"].get<double>(), 0.003);
}

TEST(ShapeFitCommand, ParaboloidFromItsOsculatingSphere) {
  const std::string dir =
      SampleAndFit("fit_paraboloid", R"({"type": "paraboloid", "vertex": [0.2, 0.1, -0.1],
      "axis": [0, 0.6, 0.8], "curvature": 0.8})",
                   "paraboloid");
  const json m = ReadJson(dir + "/fit.json")["root"];
  ASSERT_EQ(m["type"], "paraboloid");
  EXPECT_NEAR(m["curvature"].get<double>(), 0.8, 0.02);
  const double v[3] = {0.2, 0.1, -0.1};
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(m["vertex"][k].get<double>(), v[k], 5e-3);
}

TEST(ShapeFitCommand, CapsuleFromACylinder) {
  const std::string dir = SampleAndFit("fit_capsule", R"({"type": "skeleton_offset",
      "skeleton": {"segments": [[[0, 0, -0.5], [0, 0, 0.7]]]}, "radius": 0.3})",
                                       "capsule");
  const json m = ReadJson(dir + "/fit.json")["root"];
  ASSERT_EQ(m["type"], "skeleton_offset");
  EXPECT_NEAR(m["radius"].get<double>(), 0.3, 2e-3);
  const json seg = m["skeleton"]["segments"][0];
  const double z0 = seg[0][2], z1 = seg[1][2];
  EXPECT_NEAR(std::min(z0, z1), -0.5, 5e-3);
  EXPECT_NEAR(std::max(z0, z1), 0.7, 5e-3);
}

TEST(ShapeFitCommand, SampleWorksOnBlobsAndPolylineTubes) {
  const std::string dir = testsupport::ScratchDir("sample_new_kinds");
  WriteText(dir + "/blobs.json",
            R"({"format": "implicitfit-model", "version": 1, "root": {"type": "blobs",
      "centers": [[0, 0, 0], [0.8, 0, 0]], "weights": [2, 2], "widths": [3, 3], "threshold": 1, "kernel": "gaussian"}})");
  WriteText(dir + "/tube.json",
            R"({"format": "implicitfit-model", "version": 1, "root": {"type": "skeleton_offset",
      "skeleton": {"polyline": [[0, 0, 0], [1, 0, 0], [1, 1, 0]]}, "radius": 0.2}})");
  for (const std::string name : {"blobs", "tube"}) {
    const auto s = RunCommand(kCli + " sample " + dir + "/" + name +
                              ".json --count 500 --seed 1 --out " + dir + "/" + name + ".xyz");
    ASSERT_EQ(s.exit_code, 0) << s.err;
    const auto e =
        RunCommand(kCli + " eval " + dir + "/" + name + ".json " + dir + "/" + name + ".xyz");
    ASSERT_EQ(e.exit_code, 0) << e.err;
    std::istringstream values(e.out);
    double v, worst = 0;
    int n = 0;
    while (values >> v) worst = std::max(worst, std::abs(v)), ++n;
    EXPECT_EQ(n, 500);
    EXPECT_LT(worst, 1e-9) << name;
  }
}

}  // namespace
