// `implicitfit reconstruct` end to end: a rounded box sampled by `sample` (noise, outliers), a
// scene file of its six face planes, then the model, mesh and report; usage errors exit 2.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "support/run_command.h"
#include "support/usage_errors.h"

namespace {

using nlohmann::json;
using testsupport::FileExists;
using testsupport::RunCommand;
using testsupport::ScratchDir;
using testsupport::Slurp;
using testsupport::WriteText;

const std::string kCli = IMPLICITFIT_CLI;

std::string Plane(int axis, int sign, double offset) {
  double n[3] = {0, 0, 0};
  n[axis] = sign;
  return R"({"type": "plane", "normal": [)" + std::to_string(n[0]) + "," + std::to_string(n[1]) +
         "," + std::to_string(n[2]) + R"(], "offset": )" + std::to_string(offset) + "}";
}

void WriteRoundedBox(const std::string& dir, int points) {
  const double half[3] = {1.0, 0.7, 0.5};
  std::string faces, scene;
  int k = 0;
  for (int a = 0; a < 3; ++a)
    for (int s : {-1, 1}) {
      faces += (k ? "," : "") + Plane(a, s, half[a]);
      scene += std::string(k ? "," : "") + R"({"name": "p)" + std::to_string(k) +
               R"(", "model": )" + Plane(a, s, half[a]) +
               R"(, "points": 100, "rms_distance": 0.004, "normal_side": "outward"})";
      ++k;
    }
  WriteText(dir + "/truth.json",
            R"({"format": "implicitfit-model", "version": 1, "root": {"type": "intersection",
    "delta": 0.2, "epsilon": 0.12, "order": 3, "children": [)" +
                faces + "]}}");
  WriteText(dir + "/scene.json",
            R"({"format": "implicitfit-scene", "version": 1, "cloud": "cloud.xyz", "points": )" +
                std::to_string(points) + R"(, "unassigned": 0, "primitives": [)" + scene + "]}");
}

TEST(ReconstructCommand, RoundedBoxGivesModelMeshAndReportWithTheFillet) {
  const std::string dir = ScratchDir("reconstruct");
  WriteRoundedBox(dir, 4000);
  ASSERT_EQ(RunCommand(kCli + " sample " + dir +
                       "/truth.json --count 4000 --noise 0.004 --outliers 0.05 --seed 3 --out " +
                       dir + "/cloud.xyz")
                .exit_code,
            0);
  const auto r =
      RunCommand(kCli + " reconstruct " + dir + "/cloud.xyz --scene " + dir + "/scene.json --out " +
                 dir + "/model.json --mesh " + dir + "/mesh.ply --report " + dir + "/report.json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json report = json::parse(Slurp(dir + "/report.json"));
  EXPECT_TRUE(report["success"].get<bool>());
  EXPECT_TRUE(report["bounded"].get<bool>());
  EXPECT_GE(report["normal_sign_agreement"].get<double>(), 0.99);
  EXPECT_LE(report["rms_distance"].get<double>(), 1.5 * 0.004);
  ASSERT_EQ(report["blends"].size(), 1u);
  const double truth_radius = 0.2 / (4 * (1 - std::cos(M_PI / 4)));
  EXPECT_NEAR(report["blends"][0]["fillet_radius"].get<double>(), truth_radius, 0.1 * truth_radius);
  EXPECT_GT(report["blends"][0]["standard_deviations"]["delta"].get<double>(), 0.0);
  const json model = json::parse(Slurp(dir + "/model.json"));
  EXPECT_EQ(model["root"]["type"], "intersection");
  EXPECT_EQ(model["root"]["children"].size(), 6u);
  EXPECT_NE(Slurp(dir + "/mesh.ply").find("element face "), std::string::npos);
}

// Without --scene, reconstruct runs detect on the cloud: a sharp box (six planes) sampled with
// noise comes back as a bounded solid through its points.
TEST(ReconstructCommand, WithoutASceneItDetectsThePrimitivesItself) {
  const std::string dir = ScratchDir("reconstruct_detect");
  std::string planes;
  const double half[3] = {0.5, 0.4, 0.3};
  for (int a = 0; a < 3; ++a)
    for (int s = -1; s <= 1; s += 2) {
      double n[3] = {0, 0, 0};
      n[a] = s;
      planes += std::string(planes.empty() ? "" : ",") + R"({"type": "plane", "normal": [)" +
                std::to_string(n[0]) + "," + std::to_string(n[1]) + "," + std::to_string(n[2]) +
                R"(], "offset": )" + std::to_string(half[a]) + "}";
    }
  WriteText(
      dir + "/box.json",
      R"({"format": "implicitfit-model", "version": 1, "root": {"type": "intersection", "delta": 0.1, "epsilon": 0.05, "order": 0, "children": [)" +
          planes + "]}}");
  ASSERT_EQ(RunCommand(kCli + " sample " + dir +
                       "/box.json --count 6000 --noise 0.002 --seed 5 --out " + dir + "/cloud.xyz")
                .exit_code,
            0);
  const auto r = RunCommand(kCli + " reconstruct " + dir + "/cloud.xyz --out " + dir +
                            "/model.json --report " + dir + "/report.json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json report = json::parse(Slurp(dir + "/report.json"));
  EXPECT_TRUE(report["bounded"].get<bool>());
  EXPECT_GE(report["normal_sign_agreement"].get<double>(), 0.99);
  EXPECT_LE(report["rms_distance"].get<double>(), 1.5 * 0.002);
  EXPECT_TRUE(FileExists(dir + "/model.json"));
}

// An open scan: the box without its bottom face (points whose normal is -z removed) and a scene
// of its five seen faces gives a solid closed by one closure plane, reported as not measured.
TEST(ReconstructCommand, OpenScanIsClosedAndTheClosureReported) {
  const std::string dir = ScratchDir("reconstruct_open");
  WriteText(dir + "/sharp.json",
            R"({"format": "implicitfit-model", "version": 1, "root": {"type": "intersection",
    "delta": 0.1, "epsilon": 0.05, "order": 0, "children": [)" +
                Plane(0, -1, 1.0) + "," + Plane(0, 1, 1.0) + "," + Plane(1, -1, 0.7) + "," +
                Plane(1, 1, 0.7) + "," + Plane(2, -1, 0.5) + "," + Plane(2, 1, 0.5) + "]}}");
  ASSERT_EQ(RunCommand(kCli + " sample " + dir +
                       "/sharp.json --count 5000 --noise 0.002 --seed 4 --out " + dir + "/all.xyz")
                .exit_code,
            0);
  std::string kept;
  int count = 0;
  {
    std::istringstream in(Slurp(dir + "/all.xyz"));
    std::string line;
    while (std::getline(in, line)) {
      std::istringstream fields(line);
      double v[6];
      for (double& x : v) fields >> x;
      if (!fields || v[5] < -0.9) continue;  // the bottom face is not scanned
      kept += line + "\n";
      ++count;
    }
  }
  WriteText(dir + "/cloud.xyz", kept);
  std::string scene;
  const int axis[5] = {0, 0, 1, 1, 2}, sign[5] = {-1, 1, -1, 1, 1};
  const double half[3] = {1.0, 0.7, 0.5};
  for (int k = 0; k < 5; ++k)
    scene += std::string(k ? "," : "") + R"({"name": "p)" + std::to_string(k) + R"(", "model": )" +
             Plane(axis[k], sign[k], half[axis[k]]) +
             R"(, "points": 100, "rms_distance": 0.002, "normal_side": "outward"})";
  WriteText(dir + "/open_scene.json",
            R"({"format": "implicitfit-scene", "version": 1, "cloud": "cloud.xyz", "points": )" +
                std::to_string(count) + R"(, "unassigned": 0, "primitives": [)" + scene + "]}");
  const auto r =
      RunCommand(kCli + " reconstruct " + dir + "/cloud.xyz --scene " + dir +
                 "/open_scene.json --out " + dir + "/model.json --report " + dir + "/report.json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json report = json::parse(Slurp(dir + "/report.json"));
  EXPECT_TRUE(report["bounded"].get<bool>());
  ASSERT_EQ(report["closures"].size(), 1u);
  EXPECT_FALSE(report["closures"][0]["measured"].get<bool>());
  EXPECT_LT(report["closures"][0]["normal"][2].get<double>(), -0.9999);
  EXPECT_EQ(report["separators"].size(), 0u);
  EXPECT_NE(Slurp(dir + "/model.json").find("\"closure0\""), std::string::npos);
}

TEST(ReconstructCommand, UsageErrorsExitTwoWithoutOutput) {
  const std::string dir = ScratchDir("reconstruct_bad");
  WriteRoundedBox(dir, 500);
  ASSERT_EQ(RunCommand(kCli + " sample " + dir + "/truth.json --count 400 --seed 1 --out " + dir +
                       "/cloud.xyz")
                .exit_code,
            0);
  WriteText(dir + "/bad_scene.json", R"({"format": "implicitfit-scene", "version": 1})");
  testsupport::ExpectUsageErrors(
      kCli + " reconstruct",
      {
          {dir + "/missing.xyz --scene " + dir + "/scene.json --out " + dir + "/m.json",
           "missing.xyz"},
          {dir + "/cloud.xyz --scene " + dir + "/bad_scene.json --out " + dir + "/m.json",
           "bad_scene.json"},
          {dir + "/cloud.xyz --scene " + dir + "/scene.json --out " + dir + "/m.json",
           "500 points"},
          {dir + "/cloud.xyz --scene " + dir + "/scene.json --out " + dir + "/m.json --mesh " +
               dir + "/m.obj",
           "m.obj"},
      },
      dir + "/m.json");
}

}  // namespace
