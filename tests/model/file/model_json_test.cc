#include "model/file/model_json.h"

#include <gtest/gtest.h>

#include <random>

namespace implicitfit {
namespace {

using nlohmann::json;

json Doc(const json& root) {
  return {{"format", "implicitfit-model"}, {"version", 1}, {"root", root}};
}

const char* kEveryType = R"({
  "format": "implicitfit-model", "version": 1,
  "root": {"type": "union", "delta": 0.3, "epsilon": 0.2, "order": 3, "name": "all",
    "children": [
      {"type": "plane", "normal": [0, 0, 1], "offset": -0.5},
      {"type": "sphere", "center": [0.1, 0.2, 0.3], "radius": 1.25, "fixed": ["radius"]},
      {"type": "cylinder", "point": [0, 0, 0], "axis": [0, 1, 0], "radius": 0.3},
      {"type": "cone", "apex": [0, 0, 2], "axis": [0, 0, -1], "half_angle": 0.4},
      {"type": "torus", "center": [1, 1, 1], "axis": [1, 0, 0], "major_radius": 2, "minor_radius": 0.5},
      {"type": "ellipsoid", "center": [0, 0, 0], "radii": [1, 2, 3], "axes": [[1, 0, 0], [0, 1, 0], [0, 0, 1]]},
      {"type": "quadric", "coefficients": [1, 1, -1, 0, 0, 0, 0, 0, 0, -0.25]},
      {"type": "intersection", "delta": 0.1, "epsilon": 0.1, "order": 0, "children": [
        {"type": "sphere", "center": [0, 0, 0], "radius": 3},
        {"type": "difference", "delta": 0.2, "epsilon": 0.05, "order": 1, "children": [
          {"type": "sphere", "center": [0, 0, 0], "radius": 2},
          {"type": "sphere", "center": [1, 0, 0], "radius": 1}]}]}
    ]}})";

TEST(ModelJson, ReadsEveryNodeType) {
  const Model m = ModelFromJson(json::parse(kEveryType));
  EXPECT_EQ(m.nodes().size(), 13u);
  EXPECT_EQ(m.nodes()[m.root()].type, NodeType::kUnion);
  EXPECT_EQ(m.nodes()[m.root()].name, "all");
  EXPECT_EQ(m.nodes()[m.root()].children.size(), 8u);
}

TEST(ModelJson, RoundTripIsExact) {
  const Model m = ModelFromJson(json::parse(kEveryType));
  const json written = ModelToJson(m);
  const Model again = ModelFromJson(json::parse(written.dump()));
  EXPECT_EQ(again.parameters(), m.parameters());  // bit-exact doubles
  EXPECT_EQ(ModelToJson(again), written);
  EXPECT_EQ(again.nodes()[1 + 0].fixed, std::vector<std::string>{"radius"});
}

TEST(ModelJson, RoundTripKeepsArbitraryDoublesBitExact) {
  std::mt19937_64 rng(42);
  std::uniform_real_distribution<double> u(-1e3, 1e3);
  for (int i = 0; i < 200; ++i) {
    Model m;
    m.AddPrimitive(NodeType::kSphere, {u(rng), u(rng), u(rng), std::abs(u(rng)) + 1e-9});
    const Model again = ModelFromJson(json::parse(ModelToJson(m).dump()));
    EXPECT_EQ(again.parameters(), m.parameters());
  }
}

void ExpectRefused(const json& document, const std::string& fragment) {
  try {
    ModelFromJson(document);
    ADD_FAILURE() << "accepted: " << document.dump();
  } catch (const ModelFormatError& e) {
    EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
  }
}

TEST(ModelJson, RefusesInvalidDocumentsNamingTheField) {
  ExpectRefused(json::parse(R"({"format": "x", "version": 1, "root": {}})"), "format");
  ExpectRefused(json::parse(R"({"format": "implicitfit-model", "version": 2, "root": {}})"),
                "version");
  ExpectRefused(json::parse(R"({"format": "implicitfit-model", "version": 1})"), "root: missing");
  ExpectRefused(
      json::parse(R"({"format": "implicitfit-model", "version": 1, "root": {}, "extra": 1})"),
      "extra: unknown top-level field");
  ExpectRefused(Doc({{"type", "blob"}}), "unknown node type 'blob'");
  ExpectRefused(Doc({{"type", "sphere"}, {"center", {0, 0, 0}}, {"radius", -1}}),
                "root.radius: must be > 0");
  ExpectRefused(Doc({{"type", "sphere"}, {"center", {0, 0}}, {"radius", 1}}),
                "root.center: must be an array of 3");
  ExpectRefused(Doc({{"type", "sphere"}, {"center", {0, 0, 0}}, {"radius", 1}, {"colour", "red"}}),
                "root.colour: unknown field");
  ExpectRefused(Doc({{"type", "sphere"}, {"center", {0, 0, 0}}}), "root.radius: missing");
  ExpectRefused(Doc({{"type", "sphere"}, {"center", {0, 0, "a"}}, {"radius", 1}}),
                "root.center[2]");
  ExpectRefused(Doc({{"type", "plane"}, {"normal", {0, 0, 0}}, {"offset", 1}}),
                "root.normal: must be a non-zero");
  ExpectRefused(
      Doc({{"type", "cone"}, {"apex", {0, 0, 0}}, {"axis", {0, 0, 1}}, {"half_angle", 1.6}}),
      "root.half_angle");
  ExpectRefused(Doc({{"type", "ellipsoid"},
                     {"center", {0, 0, 0}},
                     {"radii", {1, 1, 1}},
                     {"axes", {{1, 0, 0}, {1, 1, 0}}}}),
                "orthogonal");
  ExpectRefused(Doc({{"type", "quadric"}, {"coefficients", std::vector<double>(10, 0.0)}}),
                "all be zero");
  ExpectRefused(
      Doc({{"type", "sphere"}, {"center", {0, 0, 0}}, {"radius", 1}, {"fixed", {"radiu"}}}),
      "'radiu' is not a parameter");
  const json s = {{"type", "sphere"}, {"center", {0, 0, 0}}, {"radius", 1}};
  ExpectRefused(Doc({{"type", "union"},
                     {"children", {s, s}},
                     {"delta", 0.1},
                     {"epsilon", 0.2},
                     {"order", 2}}),
                "root.epsilon: must not exceed delta");
  ExpectRefused(
      Doc({{"type", "union"}, {"children", {s}}, {"delta", 0.1}, {"epsilon", 0.1}, {"order", 2}}),
      "root.children: must be an array of at least 2");
  ExpectRefused(Doc({{"type", "union"},
                     {"children", {s, s}},
                     {"delta", 0.1},
                     {"epsilon", 0.1},
                     {"order", 2.5}}),
                "root.order");
  ExpectRefused(Doc({{"type", "union"},
                     {"children", {s, {{"type", "sphere"}}}},
                     {"delta", 0.1},
                     {"epsilon", 0.1},
                     {"order", 2}}),
                "root.children[1].center: missing");
}

TEST(ModelJson, EllipsoidWritesAThirdAxisThatIsTheCrossProduct) {
  const Model m = ModelFromJson(Doc({{"type", "ellipsoid"},
                                     {"center", {0, 0, 0}},
                                     {"radii", {1, 2, 3}},
                                     {"axes", {{0, 1, 0}, {0, 0, 1}}}}));
  const json out = ModelToJson(m);
  EXPECT_EQ(out["root"]["axes"][2], json::array({1.0, 0.0, 0.0}));
}

}  // namespace
}  // namespace implicitfit
