// Box (exact SDF) and complement: closed forms derived here from the geometry, the JSON form of
// docs/maths.md TB-1, and the agreement with the sharp intersection of the six face planes (which
// is exact inside, and a lower bound outside).
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <random>

#include "model/file/model_json.h"
#include "model/model.h"
#include "support/model_document.h"

namespace implicitfit {
namespace {

using Vec = Eigen::Vector3d;

Model AxisBox(const Vec& c, const Vec& h) {
  Model m;
  m.AddPrimitive(NodeType::kBox, {c.x(), c.y(), c.z(), 1, 0, 0, 0, h.x(), h.y(), h.z()});
  return m;
}

TEST(Box, DistancesToFacesEdgesAndCornersInClosedForm) {
  const Model m = AxisBox(Vec(1, 2, 3), Vec(0.5, 1.0, 2.0));
  EXPECT_DOUBLE_EQ(m.Value(Vec(1, 2, 3)), -0.5);  // centre: nearest face x
  EXPECT_DOUBLE_EQ(m.Value(Vec(1.3, 2, 3)), -0.2);
  EXPECT_DOUBLE_EQ(m.Value(Vec(1 + 0.5 + 0.25, 2, 3)), 0.25);  // off the +x face
  // Beyond the (+x, +y) edge: distance sqrt(a^2 + b^2).
  EXPECT_NEAR(m.Value(Vec(1.5 + 0.3, 3.0 + 0.4, 3.7)), 0.5, 1e-15);
  // Beyond the (+x, -y, -z) corner: |(0.1, 0.2, 0.2)| = 0.3.
  EXPECT_NEAR(m.Value(Vec(1.6, 0.8, 0.8)), 0.3, 1e-15);
}

TEST(Box, JsonFormOfTheNotesLoadsWithItsAxes) {
  const Model m = ModelFromJson(nlohmann::json::parse(R"({"format": "implicitfit-model",
      "version": 1, "root": {"type": "box", "center": [0, 0, 1], "axes": [[0, 1, 0], [-1, 0, 0]],
      "half_sizes": [2, 1, 0.5]}})"));
  // e1 = y, e2 = -x: the half size 2 lies along y, 1 along x.
  EXPECT_NEAR(m.Value(Vec(0, 2.5, 1)), 0.5, 1e-15);
  EXPECT_NEAR(m.Value(Vec(1.5, 0, 1)), 0.5, 1e-15);
  EXPECT_NEAR(m.Value(Vec(0, 0, 1.75)), 0.25, 1e-15);
  const nlohmann::json out = ModelToJson(m)["root"];
  EXPECT_NEAR(out["axes"][0][1].get<double>(), 1.0, 1e-15);
  EXPECT_NEAR(out["axes"][1][0].get<double>(), -1.0, 1e-15);
  EXPECT_NEAR(out["axes"][2][2].get<double>(), 1.0, 1e-15);  // e3 = e1 x e2 = z
}

TEST(Box, RefusesBadFieldsNamingThePath) {
  auto load = testsupport::ModelFromRoot;
  EXPECT_THROW(
      load(
          R"({"type": "box", "center": [0,0,0], "axes": [[1,0,0],[1,1,0]], "half_sizes": [1,1,1]})"),
      ModelFormatError);
  try {
    load(R"({"type": "box", "center": [0,0,0], "axes": [[1,0,0],[0,1,0]], "half_sizes": [1,0,1]})");
    FAIL();
  } catch (const ModelFormatError& e) {
    EXPECT_NE(std::string(e.what()).find("root.half_sizes[1]"), std::string::npos) << e.what();
  }
}

TEST(Box, EqualsTheSharpIntersectionOfItsFacePlanesInsideAndBoundsItOutside) {
  const Eigen::Matrix3d r =
      Eigen::AngleAxisd(0.7, Vec(0.2, -1, 0.4).normalized()).toRotationMatrix();
  const Eigen::Quaterniond q(r);
  const Vec c(0.1, 0.2, -0.3), h(0.8, 0.5, 1.1);
  Model box, planes;
  box.AddPrimitive(NodeType::kBox,
                   {c.x(), c.y(), c.z(), q.w(), q.x(), q.y(), q.z(), h.x(), h.y(), h.z()});
  std::vector<int> faces;
  for (int i = 0; i < 3; ++i)
    for (double s : {-1.0, 1.0}) {
      const Vec n = s * r.col(i);
      faces.push_back(
          planes.AddPrimitive(NodeType::kPlane, {n.x(), n.y(), n.z(), n.dot(c) + h[i]}));
    }
  planes.AddOperator(NodeType::kIntersection, faces, 1.0, 1.0, 0);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-2, 2);
  int inside = 0;
  for (int i = 0; i < 2000; ++i) {
    const Vec x(u(rng), u(rng), u(rng));
    const double f = box.Value(x), g = planes.Value(x);
    if (g <= 0) {
      ++inside;
      EXPECT_NEAR(f, g, 1e-14);
    } else {
      EXPECT_GE(f, g - 1e-14);
    }
  }
  EXPECT_GT(inside, 100);
}

TEST(Complement, IsMinusTheChildBitForBitAndSwapsInsideAndOutside) {
  Model m = AxisBox(Vec::Zero(), Vec(1, 1, 1));
  const Model child = m;
  m.AddComposite(NodeType::kComplement, {0}, {});
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-2, 2);
  for (int i = 0; i < 100; ++i) {
    const Vec x(u(rng), u(rng), u(rng));
    EXPECT_EQ(m.Value(x), -child.Value(x));
  }
  EXPECT_GT(m.Value(Vec::Zero()), 0.0);
  const Model back = ModelFromJson(ModelToJson(m));
  EXPECT_EQ(back.nodes()[back.root()].type, NodeType::kComplement);
  EXPECT_EQ(back.Value(Vec(0.3, 2, 0.1)), m.Value(Vec(0.3, 2, 0.1)));
  EXPECT_THROW(ModelFromJson(nlohmann::json::parse(R"({"format": "implicitfit-model", "version": 1,
      "root": {"type": "complement", "children": []}})")),
               ModelFormatError);
}

}  // namespace
}  // namespace implicitfit
