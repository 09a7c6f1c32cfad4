// The bernstein_patch node of the model file (docs/model-file.md): exact round trip and strict refusal
// of invalid nodes, naming the JSON path.
#include <gtest/gtest.h>

#include <random>

#include "model/file/model_json.h"
#include "oracle/bernstein_oracle.h"

namespace implicitfit {
namespace {

using nlohmann::json;

json Doc(const json& root) {
  return {{"format", "implicitfit-model"}, {"version", 1}, {"root", root}};
}

json Patch(int k, const std::vector<double>& b) {
  return {{"type", "bernstein_patch"},
          {"degree", k},
          {"vertices", {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0, 0, 0}}},
          {"control_points", b}};
}

TEST(BernsteinJson, ReadsEvaluatesAndRoundTripsExactly) {
  std::mt19937_64 rng(51);
  std::uniform_real_distribution<double> u(-10, 10);
  for (int k = 1; k <= 5; ++k) {
    std::vector<double> b(static_cast<size_t>((k + 1) * (k + 2) * (k + 3) / 6));
    for (double& x : b) x = u(rng);
    const json sphere = {{"type", "sphere"}, {"center", {0, 0, 0}}, {"radius", 1}};
    json root = {{"type", "union"}, {"delta", 0.1}, {"epsilon", 0.1}, {"order", 2}};
    root["children"] = json::array({Patch(k, b), sphere});
    const json doc = Doc(root);
    const Model m = ModelFromJson(doc);
    ASSERT_EQ(m.nodes()[0].type, NodeType::kBernsteinPatch);
    EXPECT_EQ(m.nodes()[0].degree, k);
    const std::array<Eigen::Vector3d, 4> corners = {
        Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(0, 1, 0), Eigen::Vector3d(0, 0, 1),
        Eigen::Vector3d(0, 0, 0)};
    const Eigen::Vector3d x(0.2, -0.3, 0.4);
    const double* p = m.parameters().data() + m.nodes()[0].first_parameter;
    EXPECT_NEAR(m.EvaluateNode(0, m.parameters().data(), x.data()), oracle::Patch(k, b, corners, x),
                1e-12 * (1 + std::abs(p[0])));
    const json written = ModelToJson(m);
    EXPECT_EQ(written["root"]["children"][0], Patch(k, b));
    const Model again = ModelFromJson(json::parse(written.dump()));
    EXPECT_EQ(again.parameters(), m.parameters());
    EXPECT_EQ(ModelToJson(again), written);
  }
}

void ExpectRefused(const json& root, const std::string& fragment) {
  try {
    ModelFromJson(Doc(root));
    ADD_FAILURE() << "accepted: " << root.dump();
  } catch (const ModelFormatError& e) {
    EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
  }
}

TEST(BernsteinJson, RefusesInvalidPatchesNamingTheField) {
  const std::vector<double> ten(10, 1.0);
  json p = Patch(2, ten);
  p["control_points"] = std::vector<double>(9, 1.0);
  ExpectRefused(p, "root.control_points: must be an array of 10 numbers");
  p = Patch(2, ten);
  p["control_points"][3] = "x";
  ExpectRefused(p, "root.control_points[3]: must be a number");
  p = Patch(2, ten);
  p["degree"] = 0;
  ExpectRefused(p, "root.degree: must be an integer in 1..");
  p["degree"] = 2.5;
  ExpectRefused(p, "root.degree: missing or not an integer");
  p = Patch(2, ten);
  p.erase("degree");
  ExpectRefused(p, "root.degree");
  p = Patch(2, ten);
  p["vertices"] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  ExpectRefused(p, "root.vertices: must hold 4 points");
  p["vertices"] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0, 0}};
  ExpectRefused(p, "root.vertices[3]: must be an array of 3 numbers");
  p["vertices"] = {{1, 0, 0}, {0, 1, 0}, {1, 1, 0}, {0, 0, 0}};
  ExpectRefused(p, "root.vertices: tetrahedron is degenerate (flat)");
  p = Patch(2, ten);
  p["radius"] = 1;
  ExpectRefused(p, "root.radius: unknown field");
  p = Patch(2, ten);
  p["fixed"] = {"control_points"};
  EXPECT_EQ(ModelFromJson(Doc(p)).nodes()[0].fixed, std::vector<std::string>{"control_points"});
  p["fixed"] = {"vertices"};
  ExpectRefused(p, "root.fixed[0]: 'vertices' is not a parameter");
}

}  // namespace
}  // namespace implicitfit
