// The solid verification through the command line: `verify MODEL CLOUD` accepts a box sampled
// from itself and refuses, each with exit 1 and its reason on stderr, a single plane, a solid
// with an infinite tube, a box with an unsupported cavity and a shell whose inside is the
// data's outside; `reconstruct` writes no model when its solid fails verification (and writes
// it marked unverified with --keep-unverified); `mesh MODEL.json` with its defaults gives the
// mesh `reconstruct --mesh` wrote (the model's verified bounds set the grid).
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "support/model_document.h"
#include "support/run_command.h"

namespace {

using nlohmann::json;
using testsupport::FileExists;
using testsupport::ModelDocument;
using testsupport::RunCommand;
using testsupport::ScratchDir;
using testsupport::Slurp;
using testsupport::WriteText;

const std::string kCli = IMPLICITFIT_CLI;

std::string Plane(double nx, double ny, double nz, double offset, const std::string& name) {
  std::ostringstream s;
  s << R"({"type": "plane", "name": ")" << name << R"(", "normal": [)" << nx << "," << ny << ","
    << nz << R"(], "offset": )" << offset << "}";
  return s.str();
}

// Intersection of the six faces of the box |x| <= hx, |y| <= hy, |z| <= hz.
std::string Box(double hx, double hy, double hz, const std::string& prefix) {
  const double h[3] = {hx, hy, hz};
  std::string faces;
  int k = 0;
  for (int a = 0; a < 3; ++a)
    for (int s : {-1, 1}) {
      double n[3] = {0, 0, 0};
      n[a] = s;
      faces += (k ? "," : "") + Plane(n[0], n[1], n[2], h[a], prefix + std::to_string(k));
      ++k;
    }
  return R"({"type": "intersection", "delta": 0.1, "epsilon": 0.1, "order": 0, "children": [)" +
         faces + "]}";
}

class VerifyCommand : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = ScratchDir("verify");
    WriteText(dir_ + "/box.json", ModelDocument(Box(1, 0.7, 0.5, "p")));
    ASSERT_EQ(
        RunCommand(kCli + " sample " + dir_ +
                   "/box.json --count 4000 --noise 0.004 --seed 3 --out " + dir_ + "/cloud.xyz")
            .exit_code,
        0);
  }
  testsupport::CommandResult Verify(const std::string& root) {
    WriteText(dir_ + "/model.json", ModelDocument(root));
    return RunCommand(kCli + " verify " + dir_ + "/model.json " + dir_ + "/cloud.xyz --quiet");
  }
  std::string dir_;
};

TEST_F(VerifyCommand, AcceptsTheBoxItsCloudWasSampledFrom) {
  const auto r = Verify(Box(1, 0.7, 0.5, "p"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json v = json::parse(r.out);
  EXPECT_TRUE(v["verified"].get<bool>());
  EXPECT_TRUE(v["bounded"]["proven"].get<bool>());
  EXPECT_EQ(v["pieces"]["solids"].get<int>(), 1);
  EXPECT_EQ(v["inside_outside"]["primitives"].size(), 6u);
  EXPECT_TRUE(r.err.empty()) << r.err;  // --quiet and verified: nothing on stderr
}

TEST_F(VerifyCommand, RefusesEachFailureWithItsReason) {
  struct Case {
    std::string name, root, reason;
  } cases[] = {
      {"single plane", Plane(0, 0, 1, 0.5, "top"), "not bounded"},
      {"infinite tube",
       R"({"type": "union", "delta": 0.1, "epsilon": 0.1, "order": 0, "children": [)" +
           Box(1, 0.7, 0.5, "p") +
           R"(, {"type": "cylinder", "name": "tube", "point": [0, 0, 0], "axis": [0, 0, 1], "radius": 0.2}]})",
       "not bounded"},
      {"unsupported cavity",
       R"({"type": "difference", "delta": 0.1, "epsilon": 0.1, "order": 0, "children": [)" +
           Box(1, 0.7, 0.5, "p") +
           R"(, {"type": "sphere", "name": "void", "center": [0.2, 0, 0], "radius": 0.3}]})",
       "cavity"},
      {"swapped inside",
       R"({"type": "difference", "delta": 0.1, "epsilon": 0.1, "order": 0, "children": [)" +
           Box(1.5, 1.2, 1.0, "outer") + "," + Box(1, 0.7, 0.5, "p") + "]}",
       "inside/outside disagrees"},
  };
  for (const Case& c : cases) {
    const auto r = Verify(c.root);
    EXPECT_EQ(r.exit_code, 1) << c.name << ": " << r.err;
    EXPECT_NE(r.err.find(c.reason), std::string::npos) << c.name << ": " << r.err;
    EXPECT_FALSE(json::parse(r.out)["verified"].get<bool>()) << c.name;
  }
}

// The box's cloud with 70% outliers (uniform in the sampling box) and a scene of the box's six
// faces: the reconstruction is the box, but at most 30% of the points lie on it (the verifier
// needs half the points within 1% of the diagonal of the surface): refused.
TEST_F(VerifyCommand, ReconstructWritesNoModelWhenVerificationFails) {
  ASSERT_EQ(RunCommand(kCli + " sample " + dir_ +
                       "/box.json --count 4000 --noise 0.004 --outliers 0.7 --seed 3 --out " +
                       dir_ + "/noisy.xyz")
                .exit_code,
            0);
  std::string scene;
  const double half[3] = {1, 0.7, 0.5};
  for (int k = 0; k < 6; ++k) {
    double n[3] = {0, 0, 0};
    n[k / 2] = k % 2 ? 1 : -1;
    scene += std::string(k ? "," : "") + R"({"name": "p)" + std::to_string(k) + R"(", "model": )" +
             Plane(n[0], n[1], n[2], half[k / 2], "p" + std::to_string(k)) +
             R"(, "points": 100, "rms_distance": 0.004, "normal_side": "outward"})";
  }
  WriteText(dir_ + "/scene.json",
            R"({"format": "implicitfit-scene", "version": 1, "cloud": "noisy.xyz", "points": 4000,)"
            R"( "unassigned": 0, "primitives": [)" +
                scene + "]}");
  const std::string base = kCli + " reconstruct " + dir_ + "/noisy.xyz --scene " + dir_ +
                           "/scene.json --out " + dir_ + "/m.json --mesh " + dir_ +
                           "/m.ply --report " + dir_ + "/r.json";
  auto r = RunCommand(base + " --quiet");
  ASSERT_EQ(r.exit_code, 1) << r.err;
  EXPECT_NE(r.err.find("not verified"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("explains"), std::string::npos) << r.err;
  EXPECT_FALSE(FileExists(dir_ + "/m.json"));
  EXPECT_FALSE(FileExists(dir_ + "/m.ply"));
  const json report = json::parse(Slurp(dir_ + "/r.json"));
  EXPECT_FALSE(report["success"].get<bool>());
  EXPECT_FALSE(report["model_written"].get<bool>());
  EXPECT_FALSE(report["verification"]["verified"].get<bool>());
  EXPECT_LE(report["verification"]["inside_outside"]["explained"].get<double>(), 0.35);

  r = RunCommand(base + " --quiet --keep-unverified");
  ASSERT_EQ(r.exit_code, 1) << r.err;
  ASSERT_TRUE(FileExists(dir_ + "/m.json"));
  EXPECT_TRUE(FileExists(dir_ + "/m.ply"));
  const json model = json::parse(Slurp(dir_ + "/m.json"));
  EXPECT_FALSE(model["verification"]["verified"].get<bool>());
  EXPECT_NE(model["verification"]["reason"].get<std::string>().find("explains"), std::string::npos);
  EXPECT_TRUE(json::parse(Slurp(dir_ + "/r.json"))["model_written"].get<bool>());
  // `verify` of the kept model says the same
  const auto v = RunCommand(kCli + " verify " + dir_ + "/m.json " + dir_ + "/noisy.xyz --quiet");
  EXPECT_EQ(v.exit_code, 1);
  EXPECT_NE(v.err.find("explains"), std::string::npos) << v.err;
}

TEST_F(VerifyCommand, MeshOfTheWrittenModelReproducesReconstructMesh) {
  const auto r = RunCommand(kCli + " reconstruct " + dir_ + "/cloud.xyz --out " + dir_ +
                            "/m.json --mesh " + dir_ + "/m.ply");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  // progress on stderr, one line per stage, and the summary last
  EXPECT_NE(r.err.find("implicitfit reconstruct: verification"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("implicitfit reconstruct: verified solid"), std::string::npos) << r.err;
  const json model = json::parse(Slurp(dir_ + "/m.json"));
  ASSERT_TRUE(model.contains("bounds"));
  EXPECT_TRUE(model["verification"]["verified"].get<bool>());
  // every leaf of the solid is named, and the report's expression uses those names
  const std::string text = Slurp(dir_ + "/m.json");
  EXPECT_NE(text.find("\"name\": \"p0\""), std::string::npos);
  ASSERT_EQ(RunCommand(kCli + " mesh " + dir_ + "/m.json --out " + dir_ + "/again.ply").exit_code,
            0);
  EXPECT_EQ(Slurp(dir_ + "/again.ply"), Slurp(dir_ + "/m.ply"));
}

// Output paths are checked before any work: a missing folder for any output exits 2 at once
// (the cloud is never read: it does not even exist here), naming the output, and writes
// nothing; a run whose mesh folder is missing leaves no model behind either.
TEST_F(VerifyCommand, ReconstructChecksOutputsBeforeWorkAndLeavesNothingBehind) {
  auto r = RunCommand(kCli + " reconstruct " + dir_ + "/absent.xyz --out " + dir_ +
                      "/no_such_folder/m.json --quiet");
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("no_such_folder/m.json"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("no_such_folder does not exist"), std::string::npos) << r.err;
  r = RunCommand(kCli + " reconstruct " + dir_ + "/cloud.xyz --out " + dir_ + "/m.json --mesh " +
                 dir_ + "/no_such_folder/m.ply --report " + dir_ + "/r.json --quiet");
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("no_such_folder/m.ply"), std::string::npos) << r.err;
  EXPECT_FALSE(FileExists(dir_ + "/m.json"));
  EXPECT_FALSE(FileExists(dir_ + "/r.json"));
  // the same cloud into an existing folder works (the check refuses only what must fail)
  r = RunCommand(kCli + " reconstruct " + dir_ + "/cloud.xyz --out " + dir_ + "/m.json --mesh " +
                 dir_ + "/m.ply --quiet");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(FileExists(dir_ + "/m.json"));
  EXPECT_TRUE(FileExists(dir_ + "/m.ply"));
}

}  // namespace
