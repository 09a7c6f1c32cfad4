// `implicitfit check` on whole model trees and the additive fields of issue #12: the witness
// tree of docs/maths.md LP-4 a is not certified (exit 1; --patches-only keeps the old vacuous verdict), a
// convex-smoothing intersection of planes and a sphere is; patches carry the G-2/G-3/G-4 fields.
// Patch shape-control options of `fit` reject bad values with exit 2.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "support/run_command.h"

namespace {

using nlohmann::json;
using testsupport::RunCommand;
using testsupport::WriteText;
const std::string kCli = IMPLICITFIT_CLI;

json Plane(double nx, double ny, double nz, double d) {
  return {{"type", "plane"}, {"normal", {nx, ny, nz}}, {"offset", d}};
}

json Document(const json& root) {
  return {{"format", "implicitfit-model"}, {"version", 1}, {"root", root}};
}

TEST(CheckTree, TheWitnessTreeIsNotCertifiedAndExits1) {
  const std::string dir = testsupport::ScratchDir("check_tree_witness");
  const json witness = Document({{"type", "intersection"},
                                 {"delta", 1.0},
                                 {"epsilon", 1.0},
                                 {"order", 3},
                                 {"children", {Plane(1, 0, 0, 0), Plane(0, 1, 0, 0)}}});
  WriteText(dir + "/w.json", witness.dump());
  const auto r = RunCommand(kCli + " check --json " + dir + "/w.json");
  EXPECT_EQ(r.exit_code, 1) << r.err;
  const json report = json::parse(r.out);
  EXPECT_EQ(report["convex"], false);
  const json& file = report["files"][0];
  EXPECT_EQ(file["convex"], false);
  EXPECT_TRUE(file["patches"].empty());
  EXPECT_EQ(file["tree"]["class"], "not-certified");
  EXPECT_EQ(file["tree"]["certified"], false);
  ASSERT_EQ(file["nodes"].size(), 3u);
  EXPECT_EQ(file["nodes"][2]["node"], "root");
  EXPECT_EQ(file["nodes"][0]["class"], "convex-function");
  EXPECT_NE(r.err.find("not certified convex"), std::string::npos) << r.err;
  // The old verdict on request.
  const auto old = RunCommand(kCli + " check --json --patches-only " + dir + "/w.json");
  EXPECT_EQ(old.exit_code, 0);
  EXPECT_EQ(json::parse(old.out)["files"][0]["convex"], true);
  // The same tree with convex smoothing: certified, exit 0.
  json convex = witness;
  convex["root"].erase("epsilon");
  convex["root"]["smoothing"] = "convex";
  WriteText(dir + "/c.json", convex.dump());
  const auto c = RunCommand(kCli + " check --json " + dir + "/c.json");
  EXPECT_EQ(c.exit_code, 0) << c.err;
  EXPECT_EQ(json::parse(c.out)["files"][0]["tree"]["class"], "convex-function");
  // A torus alone: not certified (it used to be reported convex).
  WriteText(dir + "/t.json", Document({{"type", "torus"},
                                       {"center", {0, 0, 0}},
                                       {"axis", {0, 0, 1}},
                                       {"major_radius", 1.0},
                                       {"minor_radius", 0.3}})
                                 .dump());
  EXPECT_EQ(RunCommand(kCli + " check " + dir + "/t.json").exit_code, 1);
}

TEST(CheckTree, PatchesCarryTheNewCertificateFields) {
  const std::string dir = testsupport::ScratchDir("check_tree_patch");
  // |x|^2 - 0.25 on the reference tetrahedron (degree 2): b_ij = x_i . x_j - 0.25.
  const json patch = {
      {"type", "bernstein_patch"},
      {"degree", 2},
      {"vertices", {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0, 0, 0}}},
      {"control_points", {0.75, -0.25, -0.25, -0.25, 0.75, -0.25, -0.25, 0.75, -0.25, -0.25}}};
  WriteText(dir + "/p.json", Document(patch).dump());
  const auto r = RunCommand(kCli + " check --json " + dir + "/p.json");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  const json p = json::parse(r.out)["files"][0]["patches"][0];
  // Hess f = 2 I: C^mu = I (A^mu = E^T E = I here), bound k(k-1) * 1 = 2.
  EXPECT_NEAR(p["min_eigenvalue_cartesian"].get<double>(), 1.0, 1e-12);
  EXPECT_NEAR(p["hessian_lower_bound"].get<double>(), 2.0, 1e-12);
  EXPECT_EQ(p["finsler"]["convex"], true);
  EXPECT_EQ(p["locally_convex"], true);
  ASSERT_EQ(p["edges"].size(), 6u);
  // Edge x1 x4: f(t e1) = t^2 - 0.25, one crossing at t = 0.5; control points 0.75, -0.25, -0.25.
  EXPECT_EQ(p["edges"][2]["vertices"], json({0, 3}));
  EXPECT_EQ(p["edges"][2]["sign_changes"], 1);
  EXPECT_EQ(json::parse(r.out)["files"][0]["tree"]["class"], "convex-function");
}

TEST(FitShapeControl, BadOptionsExit2) {
  const std::string dir = testsupport::ScratchDir("fit_shape_bad");
  WriteText(dir + "/c.xyz", "0 0 0 0 0 1\n1 0 0 0 0 1\n");
  for (const std::string args :
       {"--model quadric-patch --vertex-normal 5=0,0,1",
        "--model quadric-patch --vertex-normal 1=0,0", "--model quadric-patch --through-edge 2,2",
        "--model quadric-patch --through-vertex 1 --convex",
        "--model quadric-patch --vertex-normal 1=0,0,1 --vertex-normal 2=0,0,1",
        "--model sphere --through-vertex 1"}) {
    const auto r = RunCommand(kCli + " fit " + dir + "/c.xyz --out " + dir + "/m.json " + args);
    EXPECT_EQ(r.exit_code, 2) << args << ": " << r.err;
    EXPECT_FALSE(testsupport::FileExists(dir + "/m.json")) << args;
  }
}

}  // namespace
