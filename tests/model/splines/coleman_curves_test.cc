// Coleman's curve features and surface cords (docs/maths.md CO-2): the plateau closed form along
// a straight curve above a planar core (zero set z = R_C + D + W + R/2 within |y| <= W of it,
// z = R_C/2 beyond W + R, by bisection to 1e-12, every flare); one vertex is the point feature;
// JSON round trip; a cord on the unit sphere is a great-circle arc ending at its target's foot.
#include <gtest/gtest.h>

#include <cmath>

#include "model/file/model_json.h"
#include "model/model.h"
#include "model/primitives/surface_cord.h"
#include "support/root_along_z.h"

namespace implicitfit {
namespace {

using Vec = Eigen::Vector3d;
using testsupport::RootAlongZ;
constexpr double kRc = 0.4, kW = 0.3, kD = 0.25, kR = 0.2;

Model Ridge(double flare) {
  Model m;
  const int core = m.AddPrimitive(NodeType::kPlane, {0, 0, 1, 0});  // core z <= 0
  // A curve on the isosurface z = R_C / 2 along the x axis, bent in x only (three vertices).
  m.AddColemanCurveFeatures(core, kRc, {},
                            {{-3, 0, kRc / 2, 0.5, 0, kRc / 2, 3, 0, kRc / 2, kW, kD, kR, flare}});
  return m;
}

TEST(ColemanCurveFeatures, RidgeClosedFormForEveryFlare) {
  for (double flare : {0.0, 0.5, 1.0}) {
    const Model m = Ridge(flare);
    for (double x : {-2.0, 0.0, 0.3, 1.7})
      for (double y : {0.0, 0.15, -kW}) {
        EXPECT_NEAR(RootAlongZ(m, x, y, 0.5, 2.0), kRc + kD + kW + kR / 2, 1e-12)
            << "flare " << flare << " x " << x << " y " << y;
      }
    for (double y : {kW + kR, -0.9, 2.0})
      EXPECT_NEAR(RootAlongZ(m, 1.0, y, 0.01, 0.39), kRc / 2, 1e-12) << "flare " << flare;
  }
}

TEST(ColemanCurveFeatures, OneVertexIsThePointFeature) {
  Model point, curve;
  const int a = point.AddPrimitive(NodeType::kPlane, {0, 0, 1, 0});
  point.AddColemanFeatures(a, kRc, {0.1, 0.2, kRc / 2, kW, kD, kR, 0.3});
  const int b = curve.AddPrimitive(NodeType::kPlane, {0, 0, 1, 0});
  curve.AddColemanCurveFeatures(b, kRc, {}, {{0.1, 0.2, kRc / 2, kW, kD, kR, 0.3}});
  for (const Vec& x : {Vec(0, 0, 0.5), Vec(0.3, -0.1, 0.9), Vec(1, 1, 0.1), Vec(0.2, 0.25, 1.2)})
    EXPECT_NEAR(point.Value(x), curve.Value(x), 1e-14) << x.transpose();
}

TEST(ColemanCurveFeatures, JsonRoundTripAndRefusals) {
  const Model m = Ridge(0.5);
  const nlohmann::json j = ModelToJson(m);
  const Model back = ModelFromJson(j);
  EXPECT_EQ(back.parameters(), m.parameters());
  EXPECT_EQ(ModelToJson(back), j);
  EXPECT_EQ(back.ParameterNames().size(), m.parameters().size());
  nlohmann::json bad = j;
  bad["root"]["curve_features"][0]["width"] = 0;
  EXPECT_THROW(ModelFromJson(bad), ModelFormatError);
  bad = j;
  bad["root"]["curve_features"][0]["curve"] = nlohmann::json::array();
  EXPECT_THROW(ModelFromJson(bad), ModelFormatError);
}

TEST(SurfaceCord, FollowsAGreatCircleOnTheSphere) {
  Model sphere;
  sphere.AddPrimitive(NodeType::kSphere, {0, 0, 0, 1});
  SurfaceCordOptions o;
  o.step = 0.01;
  const std::vector<Vec> guide = {Vec(1.3, 0, 0), Vec(0, 1.3, 0)};
  const SurfaceCord cord = GrowSurfaceCord(sphere, guide, o);
  ASSERT_TRUE(cord.reached);
  double length = 0.0;
  for (size_t k = 0; k < cord.points.size(); ++k) {
    EXPECT_NEAR(cord.points[k].norm(), 1.0, 1e-10);
    EXPECT_NEAR(cord.points[k].z(), 0.0, 1e-12);
    if (k > 0) length += (cord.points[k] - cord.points[k - 1]).norm();
  }
  EXPECT_LE((cord.points.front() - Vec(1, 0, 0)).norm(), 1e-12);
  // The end: the foot of the target on the cord, which on the sphere is the target's radial
  // projection (0, 1, 0); the cord is the quarter great circle, its chords h^3/24 short per step.
  EXPECT_LE((cord.points.back() - Vec(0, 1, 0)).norm(), 1e-9);
  EXPECT_NEAR(length, M_PI / 2, 1e-4);
  for (size_t k = 1; k < cord.points.size(); ++k)  // monotone along the arc: no fold back
    EXPECT_GT(std::atan2(cord.points[k].y(), cord.points[k].x()),
              std::atan2(cord.points[k - 1].y(), cord.points[k - 1].x()));
  EXPECT_GT(cord.points.size(), 150u);
  EXPECT_THROW(GrowSurfaceCord(sphere, {Vec(1, 0, 0)}), std::invalid_argument);
}

}  // namespace
}  // namespace implicitfit
