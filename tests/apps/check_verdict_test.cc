// `implicitfit check`'s file verdict (issue 28): the conjunction of the tree's certificate and
// every patch's and mesh's. A certified convex patch in a union with a sphere 6 units away is
// not convex (the midpoint between them is outside: checked here by evaluating the tree); a
// certified bernstein_mesh is a convex-function node on its box, so it composes; every verdict
// names what it rests on (node, certificate, tetrahedron or box).
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>

#include "model/bernstein/bernstein_conversion.h"
#include "model/bernstein/bernstein_mesh.h"
#include "model/file/model_json.h"
#include "support/run_command.h"

namespace {

using nlohmann::json;
using testsupport::RunCommand;
using testsupport::WriteText;
const std::string kCli = IMPLICITFIT_CLI;

json Document(const json& root) {
  return {{"format", "implicitfit-model"}, {"version", 1}, {"root", root}};
}

// |x|^2 - 0.25 on the tetrahedron (1,0,0), (0,1,0), (0,0,1), (0,0,0): b_ij = x_i . x_j - 0.25,
// A^mu = I (certified convex).
json ConvexPatch() {
  return {{"type", "bernstein_patch"},
          {"degree", 2},
          {"vertices", {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0, 0, 0}}},
          {"control_points", {0.75, -0.25, -0.25, -0.25, 0.75, -0.25, -0.25, 0.75, -0.25, -0.25}}};
}

json Sphere(double x, double y, double z, double r) {
  return {{"type", "sphere"}, {"center", {x, y, z}}, {"radius", r}};
}

json RunCheck(const std::string& path, int expected_exit) {
  const auto r = RunCommand(kCli + " check --json " + path);
  EXPECT_EQ(r.exit_code, expected_exit) << path << "\n" << r.out << r.err;
  return json::parse(r.out);
}

TEST(CheckVerdict, CertifiedPatchUnitedWithAFarSphereIsNotConvex) {
  const std::string dir = testsupport::ScratchDir("check_verdict_union");
  const json doc =
      Document({{"type", "union"},
                                   {"delta", 0.1},
                                   {"epsilon", 0.05},
                                   {"order", 0},
                                   {"children", {ConvexPatch(), Sphere(6, 0, 0, 0.5)}}});
  WriteText(dir + "/u.json", doc.dump());
  // The solid is not convex: both (0.1, 0.1, 0.1) and (6, 0, 0) are inside, their midpoint is
  // outside (independently of any certificate).
  const implicitfit::Model m = implicitfit::ModelFromJson(doc);
  ASSERT_LT(m.Value(Eigen::Vector3d(0.1, 0.1, 0.1)), 0.0);
  ASSERT_LT(m.Value(Eigen::Vector3d(6, 0, 0)), 0.0);
  ASSERT_GT(m.Value(Eigen::Vector3d(3.05, 0.05, 0.05)), 0.0);
  const json report = RunCheck(dir + "/u.json", 1);
  EXPECT_EQ(report["convex"], false);
  const json& file = report["files"][0];
  EXPECT_EQ(file["convex"], false);
  EXPECT_EQ(file["patches"][0]["convex"], true);  // the patch alone is certified
  EXPECT_EQ(file["verdict"]["convex"], false);
  EXPECT_NE(file["verdict"]["reason"].get<std::string>().find("union"), std::string::npos)
      << file["verdict"].dump();
  // Every operator that joins the patch to the far sphere is refused, whatever its smoothing.
  for (const json& op : {json{{"type", "union"}, {"smoothing", "convex"}, {"delta", 0.1}, {"order", 3}},
                         json{{"type", "union"}, {"delta", 0.1}, {"epsilon", 0.05}, {"order", 3}},
                         json{{"type", "difference"}, {"delta", 0.1}, {"epsilon", 0.05}, {"order", 0}}}) {
    json root = op;
    root["children"] = {ConvexPatch(), Sphere(6, 0, 0, 0.5)};
    WriteText(dir + "/o.json", Document(root).dump());
    EXPECT_EQ(RunCheck(dir + "/o.json", 1)["files"][0]["convex"], false) << op.dump();
  }
}

TEST(CheckVerdict, CertifiedPatchVerdictNamesItsTetrahedron) {
  const std::string dir = testsupport::ScratchDir("check_verdict_patch");
  WriteText(dir + "/p.json", Document(ConvexPatch()).dump());
  const json v = RunCheck(dir + "/p.json", 0)["files"][0]["verdict"];
  EXPECT_EQ(v["convex"], true);
  ASSERT_EQ(v["rests_on"].size(), 1u) << v.dump();
  EXPECT_EQ(v["rests_on"][0]["node"], "root");
  EXPECT_NE(v["rests_on"][0]["certificate"].get<std::string>().find("A^mu"), std::string::npos);
  ASSERT_EQ(v["domain"].size(), 1u) << v.dump();
  EXPECT_EQ(v["domain"][0]["tetrahedron"], json({{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0, 0, 0}}));
  // Intersected (sharp) with a sphere: still certified, resting on both.
  WriteText(dir + "/i.json", Document({{"type", "intersection"},
                                       {"delta", 0.1},
                                       {"epsilon", 0.05},
                                       {"order", 0},
                                       {"children", {ConvexPatch(), Sphere(0, 0, 0, 0.4)}}})
                                 .dump());
  const json vi = RunCheck(dir + "/i.json", 0)["files"][0]["verdict"];
  EXPECT_EQ(vi["convex"], true);
  EXPECT_EQ(vi["rests_on"].size(), 3u) << vi.dump();  // root rule, the patch, the sphere
  // Li-Phillips smoothing in the same tree: not convex (S_max is not convex).
  WriteText(dir + "/l.json", Document({{"type", "intersection"},
                                       {"delta", 0.1},
                                       {"epsilon", 0.05},
                                       {"order", 3},
                                       {"children", {ConvexPatch(), Sphere(0, 0, 0, 0.4)}}})
                                 .dump());
  EXPECT_EQ(RunCheck(dir + "/l.json", 1)["files"][0]["verdict"]["convex"], false);
}

TEST(CheckVerdict, CertifiedMeshIsAConvexFunctionNodeOnItsBox) {
  const std::string dir = testsupport::ScratchDir("check_verdict_mesh");
  implicitfit::BernsteinGrid g;
  g.origin = Eigen::Vector3d(-1, -1, -1);
  g.cell = 1.0;
  g.cells = {2, 2, 2};
  implicitfit::CartesianQuadric q;  // |x|^2 - 0.5: one quadric, so C1 across every face
  q.A = Eigen::Matrix3d::Identity();
  q.b = Eigen::Vector3d::Zero();
  q.c = -0.5;
  std::vector<double> b;
  for (long long t = 0; t < g.NumTetrahedra(); ++t) {
    const auto bt = implicitfit::QuadricToBernstein(q, g.TetrahedronOf(t), 2);
    b.insert(b.end(), bt.begin(), bt.end());
  }
  const json mesh = {{"type", "bernstein_mesh"},
                     {"degree", 2},
                     {"grid", {{"origin", {-1, -1, -1}}, {"cell", 1.0}, {"cells", {2, 2, 2}}}},
                     {"continuity", 1},
                     {"control_points", b}};
  const json plane = {{"type", "plane"}, {"normal", {0, 0, 1}}, {"offset", 0.3}};
  WriteText(dir + "/m.json", Document({{"type", "intersection"},
                                       {"smoothing", "convex"},
                                       {"delta", 0.1},
                                       {"order", 3},
                                       {"children", {mesh, plane}}})
                                 .dump());
  const json file = RunCheck(dir + "/m.json", 0)["files"][0];
  EXPECT_EQ(file["meshes"][0]["convex_on_box"], true);
  EXPECT_EQ(file["nodes"][0]["class"], "convex-function") << file["nodes"].dump();
  EXPECT_EQ(file["tree"]["class"], "convex-function");
  const json& v = file["verdict"];
  EXPECT_EQ(v["convex"], true);
  ASSERT_EQ(v["domain"].size(), 1u) << v.dump();
  EXPECT_EQ(v["domain"][0]["box"]["min"], json({-1.0, -1.0, -1.0}));
  EXPECT_EQ(v["domain"][0]["box"]["max"], json({1.0, 1.0, 1.0}));
  // United with a far sphere: refused.
  WriteText(dir + "/u.json",
            Document({{"type", "union"},
                      {"delta", 0.1},
                      {"epsilon", 0.05},
                      {"order", 0},
                      {"children", {mesh, Sphere(6, 0, 0, 0.5)}}})
                .dump());
  EXPECT_EQ(RunCheck(dir + "/u.json", 1)["files"][0]["convex"], false);
}

// `design --smoothing convex` writes a tree `check` certifies (issue 28); the default design's
// Li-Phillips smooth max over a first-order ellipsoid is refused, naming the rule.
TEST(CheckVerdict, ConvexSmoothingDesignIsCertifiedByCheck) {
  const std::string dir = testsupport::ScratchDir("check_verdict_design");
  std::string cloud;
  for (int i = 0; i < 300; ++i) {
    const double z = -1 + (2.0 * i + 1) / 300, phi = i * 2.399963229728653;
    const double x = std::sqrt(1 - z * z) * std::cos(phi), y = std::sqrt(1 - z * z) * std::sin(phi);
    cloud += std::to_string(x) + " " + std::to_string(y) + " " + std::to_string(z) + " " +
             std::to_string(x) + " " + std::to_string(y) + " " + std::to_string(z) + "\n";
  }
  WriteText(dir + "/ball.xyz", cloud);
  auto r = RunCommand(kCli + " design " + dir + "/ball.xyz --count 10 --smoothing convex --out " +
                      dir + "/c.json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json v = RunCheck(dir + "/c.json", 0)["files"][0]["verdict"];
  EXPECT_EQ(v["convex"], true);
  EXPECT_EQ(v["domain"], "everywhere");
  r = RunCommand(kCli + " design " + dir + "/ball.xyz --count 10 --out " + dir + "/l.json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json l = RunCheck(dir + "/l.json", 1)["files"][0]["verdict"];
  EXPECT_NE(l["reason"].get<std::string>().find("Li-Phillips"), std::string::npos) << l.dump();
  // A convex blend has no epsilon: refused with exit 2, no file.
  r = RunCommand(kCli + " design " + dir + "/ball.xyz --count 10 --smoothing convex --epsilon 0.01 --out " + dir + "/e.json");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_FALSE(testsupport::FileExists(dir + "/e.json"));
}

}  // namespace
