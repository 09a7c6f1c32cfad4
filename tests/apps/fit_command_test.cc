// `implicitfit fit` end to end: clouds made by `implicitfit sample` from known models, fitted
// back; the recovered parameters are compared with the models they were sampled from.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <random>
#include <regex>
#include <sstream>

#include "support/read_json.h"
#include "support/run_command.h"

namespace {

using nlohmann::json;
using testsupport::RunCommand;
using testsupport::WriteText;
const std::string kCli = IMPLICITFIT_CLI;

using testsupport::ReadJson;

TEST(FitCommand, SphereFromASampledPartialViewWithOutliers) {
  const std::string dir = testsupport::ScratchDir("fit_sphere");
  WriteText(dir + "/truth.json", R"({"format": "implicitfit-model", "version": 1,
    "root": {"type": "sphere", "center": [1, 2, 3], "radius": 0.5}})");
  ASSERT_EQ(RunCommand(kCli + " sample " + dir +
                       "/truth.json --count 3000 --noise 0.0025 --outliers 0.2 --seed 4" +
                       " --view 0,0,1 --view-angle 70 --out " + dir + "/cloud.xyz")
                .exit_code,
            0);
  const auto r = RunCommand(kCli + " fit " + dir + "/cloud.xyz --model sphere --out " + dir +
                            "/fit.json --report " + dir + "/report.json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json m = ReadJson(dir + "/fit.json")["root"];
  EXPECT_EQ(m["type"], "sphere");
  EXPECT_NEAR(m["radius"].get<double>(), 0.5, 2e-3);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(m["center"][k].get<double>(), 1.0 + k, 2e-3);
  const json report = ReadJson(dir + "/report.json");
  EXPECT_TRUE(report["success"].get<bool>());
  EXPECT_EQ(report["points"], 3000);
  EXPECT_NEAR(report["sigma"].get<double>(), 0.0025, 0.0005);
  EXPECT_GT(report["standard_deviations"]["radius"].get<double>(), 0.0);
}

TEST(FitCommand, InitFitsDeltaAndEpsilonOfABlendedModel) {
  const std::string dir = testsupport::ScratchDir("fit_init");
  WriteText(dir + "/truth.json",
            R"({"format": "implicitfit-model", "version": 1, "root": {"type": "union",
    "delta": 0.3, "epsilon": 0.2, "order": 2, "children": [
      {"type": "sphere", "center": [0, 0, 0], "radius": 1}, {"type": "sphere", "center": [1.6, 0, 0], "radius": 0.8}]}})");
  WriteText(dir + "/init.json",
            R"({"format": "implicitfit-model", "version": 1, "root": {"type": "union",
    "delta": 0.5, "epsilon": 0.1, "order": 2, "children": [
      {"type": "sphere", "center": [0.05, 0, 0.02], "radius": 0.95}, {"type": "sphere", "center": [1.55, 0.03, 0], "radius": 0.85}]}})");
  ASSERT_EQ(
      RunCommand(kCli + " sample " + dir +
                 "/truth.json --count 4000 --noise 0.002 --seed 2 --out " + dir + "/cloud.xyz")
          .exit_code,
      0);
  const auto r = RunCommand(kCli + " fit " + dir + "/cloud.xyz --init " + dir +
                            "/init.json --out " + dir + "/fit.json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json m = ReadJson(dir + "/fit.json")["root"];
  EXPECT_NEAR(m["delta"].get<double>(), 0.3, 0.03);
  EXPECT_NEAR(m["epsilon"].get<double>(), 0.2, 0.04);
  EXPECT_NEAR(m["children"][1]["radius"].get<double>(), 0.8, 2e-3);
  EXPECT_NEAR(m["children"][1]["center"][0].get<double>(), 1.6, 2e-3);
}

TEST(FitCommand, ConvexCubicPatchPassesCheck) {
  const std::string dir = testsupport::ScratchDir("fit_convex");
  WriteText(dir + "/truth.json", R"({"format": "implicitfit-model", "version": 1,
    "root": {"type": "ellipsoid", "center": [0, 0, 0], "radii": [1.5, 1, 0.7], "axes": [[1, 0, 0], [0, 1, 0]]}})");
  ASSERT_EQ(RunCommand(kCli + " sample " + dir +
                       "/truth.json --count 1500 --noise 0.005 --view 0,0,1 --view-angle 50" +
                       " --out " + dir + "/cap.xyz")
                .exit_code,
            0);
  const auto r = RunCommand(kCli + " fit " + dir + "/cap.xyz --model cubic-patch --convex --out " +
                            dir + "/patch.json --report " + dir + "/report.json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto check = RunCommand(kCli + " check " + dir + "/patch.json --json");
  EXPECT_EQ(check.exit_code, 0) << check.out << check.err;
  EXPECT_TRUE(json::parse(check.out)["convex"].get<bool>());
  const json report = ReadJson(dir + "/report.json");
  EXPECT_LE(report["rms_distance"].get<double>(), 1.5 * 0.005);
  EXPECT_LE(report["rms_distance"].get<double>(),
            1.1 * report["unconstrained_rms_distance"].get<double>());
}

// Fit4CAD PC35 (six cylinders and two spheres, GPL-3: read from ../shared/data only): the
// cylinder fit is one of its cylinders (radius from the data set's parametric file) or a
// refusal; before the checks it returned a tilted cylinder of radius 22.56, RMS 1.31, exit 0.
TEST(FitCommand, CylinderOfFit4CadPc35IsOneOfItsCylindersOrRefused) {
  const std::string root = std::string(IMPLICITFIT_SHARED_DATA) + "/fit4cad/";
  const std::string cloud = root + "fit4cad_test_PC35.xyzl";
  if (!std::ifstream(cloud)) GTEST_SKIP() << "no " << cloud;
  std::vector<double> radii;  // "[Cylinder, [-9.525 0 0 ...": the first number is -r
  const std::string parametric =
      testsupport::Slurp(root + "fit4cad_test_PC35/test_PC35_parametric.txt");
  const std::regex cylinder(R"(Cylinder, \[(-?[0-9.]+) (-?[0-9.]+) (-?[0-9.]+))");
  for (std::sregex_iterator it(parametric.begin(), parametric.end(), cylinder), end; it != end;
       ++it)
    for (int k = 1; k <= 3; ++k)
      if (std::stod((*it)[k]) != 0) {
        radii.push_back(std::abs(std::stod((*it)[k])));
        break;
      }
  ASSERT_EQ(radii.size(), 6u);
  const std::string dir = testsupport::ScratchDir("fit_pc35");
  const auto r = RunCommand(kCli + " fit " + cloud + " --model cylinder --out " + dir +
                            "/c.json --report " + dir + "/r.json");
  const json report = ReadJson(dir + "/r.json");
  if (r.exit_code == 1) {
    EXPECT_NE(r.err.find("no cylinder explains"), std::string::npos) << r.err;
    EXPECT_FALSE(testsupport::FileExists(dir + "/c.json"));
    return;
  }
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const double radius = report["parameters"]["radius"];
  double nearest = INFINITY;
  for (double t : radii) nearest = std::min(nearest, std::abs(radius - t) / t);
  EXPECT_LT(nearest, 0.01) << radius;
  EXPECT_TRUE(report["check"]["checked"]);
  // The torus fit on the same part: its points are spheres and cylinders, never a torus.
  const auto t = RunCommand(kCli + " fit " + cloud + " --model torus --out " + dir + "/t.json");
  EXPECT_EQ(t.exit_code, 1) << t.out;
  EXPECT_NE(t.err.find("no torus explains"), std::string::npos) << t.err;
  EXPECT_FALSE(testsupport::FileExists(dir + "/t.json"));
}

TEST(FitCommand, FailuresExit1WithAReasonAndNoModel) {
  const std::string dir = testsupport::ScratchDir("fit_fail");
  std::string line;
  for (int i = 0; i < 200; ++i) line += std::to_string(i * 0.01) + " 0 0 0 0 1\n";  // collinear
  WriteText(dir + "/line.xyz", line);
  const auto r =
      RunCommand(kCli + " fit " + dir + "/line.xyz --model sphere --out " + dir + "/fit.json");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("line.xyz"), std::string::npos) << r.err;
  EXPECT_FALSE(testsupport::FileExists(dir + "/fit.json"));
}

TEST(FitCommand, InvalidOptionsExit2) {
  const std::string dir = testsupport::ScratchDir("fit_usage");
  WriteText(dir + "/c.xyz", "0 0 0 0 0 1\n1 0 0 0 0 1\n0 1 0 0 0 1\n");
  EXPECT_EQ(
      RunCommand(kCli + " fit " + dir + "/c.xyz --model blob --out " + dir + "/m.json").exit_code,
      2);
  EXPECT_EQ(
      RunCommand(kCli + " fit " + dir + "/c.xyz --model sphere --convex --out " + dir + "/m.json")
          .exit_code,
      2);
  EXPECT_EQ(RunCommand(kCli + " fit " + dir + "/c.xyz --model sphere --fix radius=x --out " + dir +
                       "/m.json")
                .exit_code,
            2);
  EXPECT_EQ(RunCommand(kCli + " fit " + dir + "/c.xyz --model sphere --fix colour=1 --out " + dir +
                       "/m.json")
                .exit_code,
            2);
  EXPECT_EQ(RunCommand(kCli + " fit " + dir + "/c.xyz --model quadric-patch --degree 7 --out " +
                       dir + "/m.json")
                .exit_code,
            2);
  EXPECT_FALSE(testsupport::FileExists(dir + "/m.json"));
}

}  // namespace

namespace {

TEST(SampleCommand, WritesPlyAndXyzThatReadBackTheSame) {
  const std::string dir = testsupport::ScratchDir("sample_formats");
  WriteText(dir + "/m.json", R"({"format": "implicitfit-model", "version": 1,
    "root": {"type": "torus", "center": [0, 0, 0], "axis": [0, 0, 1], "major_radius": 1, "minor_radius": 0.3}})");
  ASSERT_EQ(
      RunCommand(kCli + " sample " + dir + "/m.json --count 500 --seed 9 --out " + dir + "/a.xyz")
          .exit_code,
      0);
  ASSERT_EQ(
      RunCommand(kCli + " sample " + dir + "/m.json --count 500 --seed 9 --out " + dir + "/a.ply")
          .exit_code,
      0);
  // Both files hold points on the torus: eval prints |f| < 1e-9 for every one of them.
  for (const char* name : {"/a.xyz", "/a.ply"}) {
    const auto r = RunCommand(kCli + " eval " + dir + "/m.json " + dir + name);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    std::istringstream values(r.out);
    double v;
    int count = 0;
    while (values >> v) {
      EXPECT_LT(std::abs(v), 1e-9);
      ++count;
    }
    EXPECT_EQ(count, 500) << name;
  }
  EXPECT_EQ(
      RunCommand(kCli + " sample " + dir + "/m.json --count 5 --out " + dir + "/a.obj").exit_code,
      2);
  EXPECT_FALSE(testsupport::FileExists(dir + "/a.obj"));
}

}  // namespace

namespace {

// Points that fill a cube (no normals, 400 points, uniform): no surface explains them, so no
// kind's fit may claim one (it did: a sphere of radius 0.95 with every point an inlier, RMS 0.27,
// exit 0). Refused by the detector's volume rule, as `detect` refuses the cloud; a fixed
// --threshold (which says which points are inliers) is still the user's to give.
TEST(FitCommand, PointsFillingAVolumeAreRefusedByEveryKind) {
  const std::string dir = testsupport::ScratchDir("fit_volume");
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  {
    std::ofstream out(dir + "/cube.xyz");
    for (int i = 0; i < 400; ++i) out << u(rng) << ' ' << u(rng) << ' ' << u(rng) << '\n';
  }
  for (const char* kind : {"plane", "sphere", "cylinder", "cone", "torus"}) {
    const auto r = RunCommand(kCli + " fit " + dir + "/cube.xyz --model " + kind + " --out " + dir +
                              "/" + kind + ".json");
    EXPECT_EQ(r.exit_code, 1) << kind << ": " << r.out << r.err;
    EXPECT_NE(r.err.find("fill a volume"), std::string::npos) << kind << ": " << r.err;
    EXPECT_FALSE(testsupport::FileExists(dir + "/" + kind + ".json")) << kind;
  }
  const auto fixed = RunCommand(kCli + " fit " + dir + "/cube.xyz --model plane --threshold 0.05" +
                                " --out " + dir + "/fixed.json");
  EXPECT_EQ(fixed.err.find("fill a volume"), std::string::npos) << fixed.err;
  // A real surface from points alone still fits: 400 points on a sphere of radius 1 (noise
  // 0.005) without normals.
  {
    std::normal_distribution<double> g(0.0, 1.0);
    std::ofstream out(dir + "/sphere.xyz");
    for (int i = 0; i < 400; ++i) {
      double v[3] = {g(rng), g(rng), g(rng)};
      const double n = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
      const double r = 1.0 + 0.005 * g(rng);
      out << r * v[0] / n << ' ' << r * v[1] / n << ' ' << r * v[2] / n << '\n';
    }
  }
  const auto sphere =
      RunCommand(kCli + " fit " + dir + "/sphere.xyz --model sphere --out " + dir + "/s.json");
  EXPECT_EQ(sphere.exit_code, 0) << sphere.err;
}

}  // namespace
