// Paraboloid (docs/maths.md LP-2) and the plane's point+normal input form: closed forms derived
// here, kappa = 0 against the plane, the sign of the curvature, the JSON forms of docs/maths.md
// LP-2.
#include <gtest/gtest.h>

#include <random>

#include "model/file/model_json.h"
#include "model/model.h"
#include "support/model_document.h"

namespace implicitfit {
namespace {

using Vec = Eigen::Vector3d;

using testsupport::ModelFromRoot;

TEST(Paraboloid, ZeroCurvatureIsThePlaneBitForBit) {
  const Vec p(0.3, -1.2, 0.7), a(0.48, -0.6, 0.64);
  Model paraboloid, plane;
  paraboloid.AddPrimitive(NodeType::kParaboloid, {p.x(), p.y(), p.z(), a.x(), a.y(), a.z(), 0.0});
  plane.AddPrimitive(NodeType::kPlane,
                     {a.x(), a.y(), a.z(), a.x() * p.x() + a.y() * p.y() + a.z() * p.z()});
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-5, 5);
  for (int i = 0; i < 1000; ++i) {
    const Vec x(u(rng), u(rng), u(rng));
    EXPECT_EQ(paraboloid.Value(x), plane.Value(x)) << x.transpose();
  }
}

TEST(Paraboloid, ValuesInClosedFormAndTheSignOfTheCurvature) {
  // Vertex at the origin, axis +z, kappa = 2: f = z + x^2 + y^2.
  const Model convex = ModelFromRoot(
      R"({"type": "paraboloid", "vertex": [0, 0, 0], "axis": [0, 0, 3], "curvature": 2})");
  EXPECT_DOUBLE_EQ(convex.Value(Vec(1, 2, -1)), -1.0 + 5.0);
  EXPECT_DOUBLE_EQ(convex.Value(Vec(0, 0, -0.5)), -0.5);
  EXPECT_NEAR((convex.Gradient(Vec::Zero()) - Vec(0, 0, 1)).norm(), 0.0, 1e-15);
  // kappa > 0: the midpoint of two inside points is inside (convex solid); kappa < 0: a chord
  // between two inside points leaves the solid.
  const Vec a(-1, 0, -1.05), b(1, 0, -1.05);
  EXPECT_LT(convex.Value(a), 0.0);
  EXPECT_LT(convex.Value(b), 0.0);
  EXPECT_LT(convex.Value((a + b) / 2), 0.0);
  const Model concave = ModelFromRoot(
      R"({"type": "paraboloid", "vertex": [0, 0, 0], "axis": [0, 0, 1], "curvature": -2})");
  const Vec c(-1, 0, 0.95), d(1, 0, 0.95);
  EXPECT_LT(concave.Value(c), 0.0);
  EXPECT_LT(concave.Value(d), 0.0);
  EXPECT_GT(concave.Value((c + d) / 2), 0.0);
}

TEST(PlaneByPointAndNormal, IsTheSignedDistanceAndIsWrittenAsNormalAndOffset) {
  const Model m = ModelFromRoot(R"({"type": "plane", "point": [1, 2, 3], "normal": [0, 0, 2]})");
  EXPECT_DOUBLE_EQ(m.Value(Vec(5, -7, 4.5)), 1.5);
  const nlohmann::json out = ModelToJson(m)["root"];
  EXPECT_EQ(out["normal"], nlohmann::json::array({0.0, 0.0, 1.0}));
  EXPECT_EQ(out["offset"].get<double>(), 3.0);
  EXPECT_FALSE(out.contains("point"));
  EXPECT_THROW(
      ModelFromRoot(R"({"type": "plane", "point": [1, 2, 3], "normal": [0, 0, 1], "offset": 3})"),
      ModelFormatError);
  EXPECT_THROW(
      ModelFromRoot(
          R"({"type": "paraboloid", "vertex": [0, 0, 0], "axis": [0, 0, 0], "curvature": 1})"),
      ModelFormatError);
}

}  // namespace
}  // namespace implicitfit
