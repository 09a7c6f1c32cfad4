// Morph node (docs/maths.md TB-4): t = 1 and t = 0 reproduce the children bit for bit, values in
// between are the convex combination, the JSON form of docs/maths.md TB-4 loads and t outside [0, 1] is
// refused with its path.
#include <gtest/gtest.h>

#include <random>

#include "model/model.h"
#include "model/file/model_json.h"

namespace implicitfit {
namespace {

using Vec = Eigen::Vector3d;

Model SphereBoxMorph(double t) {
  Model m;
  const int a = m.AddPrimitive(NodeType::kSphere, {0.1, 0.2, 0.3, 1.0});
  const int b = m.AddPrimitive(NodeType::kBox, {0, 0, 0, 1, 0, 0, 0, 0.7, 0.5, 0.9});
  m.AddComposite(NodeType::kMorph, {a, b}, {t});
  return m;
}

TEST(Morph, EndValuesReproduceTheChildrenBitForBit) {
  Model sphere, box;
  sphere.AddPrimitive(NodeType::kSphere, {0.1, 0.2, 0.3, 1.0});
  box.AddPrimitive(NodeType::kBox, {0, 0, 0, 1, 0, 0, 0, 0.7, 0.5, 0.9});
  const Model at_a = SphereBoxMorph(1.0), at_b = SphereBoxMorph(0.0), mid = SphereBoxMorph(0.3);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-2, 2);
  for (int i = 0; i < 500; ++i) {
    const Vec x(u(rng), u(rng), u(rng));
    EXPECT_EQ(at_a.Value(x), sphere.Value(x));
    EXPECT_EQ(at_b.Value(x), box.Value(x));
    EXPECT_NEAR(mid.Value(x), 0.3 * sphere.Value(x) + 0.7 * box.Value(x), 1e-15);
  }
}

TEST(Morph, JsonFormOfTheNotesRoundTripsAndRefusesTOutsideTheUnitInterval) {
  const std::string head =
      R"({"format": "implicitfit-model", "version": 1, "root": {"type": "morph",
      "children": [{"type": "sphere", "center": [0, 0, 0], "radius": 1},
                   {"type": "sphere", "center": [0, 0, 0], "radius": 2}], "t": )";
  const Model m = ModelFromJson(nlohmann::json::parse(head + "0.25}}"));
  EXPECT_DOUBLE_EQ(m.Value(Vec::Zero()), -0.25 - 0.75 * 2.0);
  const Model back = ModelFromJson(ModelToJson(m));
  EXPECT_EQ(ModelToJson(back), ModelToJson(m));
  try {
    ModelFromJson(nlohmann::json::parse(head + "1.5}}"));
    FAIL();
  } catch (const ModelFormatError& e) {
    EXPECT_NE(std::string(e.what()).find("root.t"), std::string::npos) << e.what();
  }
  EXPECT_THROW(ModelFromJson(nlohmann::json::parse(R"({"format": "implicitfit-model", "version": 1,
      "root": {"type": "morph", "children": [{"type": "sphere", "center": [0, 0, 0], "radius": 1}],
      "t": 0.5}})")),
               ModelFormatError);
}

}  // namespace
}  // namespace implicitfit
