// Coleman's features in docs/maths.md CO-2's own JSON form: "features" on a skeleton_offset node in
// field mode (i = s(d; 0, R_C), R_C = the node's "radius", iso 1/2). The model is loaded from a
// JSON text written by hand from docs/maths.md CO-2, and checked against its closed form: core =
// the plane z = 0 (here a large triangle skeleton: d = z above it, as for the half-space), a
// point feature above the origin; the zero set is z = R_C + D + W + R/2 for rho <= W and
// z = R_C/2 for rho >= W + R, whatever the flare, found by bisection along z to 1e-12.
// Also: the triangle skeleton's distance against brute force; the flare's two projections
// (flare 0: p1, the plane through c(f) normal to u; flare 1: p2, the nearest core point) on a
// curved core, against values worked out by hand; exact Jets on a curved core.
#include <ceres/ceres.h>
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "model/file/model_json.h"
#include "model/model.h"
#include "support/derivative_check.h"
#include "support/model_value_cost.h"
#include "support/root_along_z.h"

namespace implicitfit {
namespace {

using Vec = Eigen::Vector3d;
using nlohmann::json;
using testsupport::ModelValueCost;
using testsupport::RootAlongZ;

// Written from docs/maths.md CO-2 (node fields) and CO-1 (the triangles skeleton), not from the
// code.
constexpr const char* kNotesModel = R"({
  "format": "implicitfit-model", "version": 1,
  "root": {
    "type": "skeleton_offset",
    "skeleton": {"triangles": [[[-50, -50, 0], [50, -50, 0], [0, 50, 0]]]},
    "radius": 0.4,
    "features": [{"point": [0, 0, 0.2], "width": 0.3, "depth": 0.25, "radius": 0.2,
                  "flare": 0.5}]
  }
})";
constexpr double kRc = 0.4, kW = 0.3, kD = 0.25, kR = 0.2;

Model NotesModel(double flare) {
  json j = json::parse(kNotesModel);
  j["root"]["features"][0]["flare"] = flare;
  return ModelFromJson(j);
}

TEST(ColemanNotesForm, LoadsAsWrittenAndWritesTheSameForm) {
  const Model m = ModelFromJson(json::parse(kNotesModel));
  const json out = ModelToJson(m);
  EXPECT_EQ(out["root"]["type"], "skeleton_offset");
  EXPECT_EQ(out["root"], json::parse(kNotesModel)["root"]);
  EXPECT_EQ(ModelToJson(ModelFromJson(out)), out);
  const std::vector<std::string> names = m.ParameterNames();
  ASSERT_EQ(names.size(), 9u + 1u + 7u);
  EXPECT_EQ(names[9], "root.radius");
  EXPECT_EQ(names[10], "root.features[0]");
  EXPECT_EQ(names[16], "root.features[6]");
}

TEST(ColemanNotesForm, PlateauClosedFormForEveryFlare) {
  for (double flare : {0.0, 0.5, 1.0}) {
    const Model m = NotesModel(flare);
    for (double rho : {0.0, 0.1, 0.2, kW}) {
      const double c = std::cos(0.7), s = std::sin(0.7);
      EXPECT_NEAR(RootAlongZ(m, rho * c, rho * s, 0.5, 2.0), kRc + kD + kW + kR / 2, 1e-12)
          << "flare " << flare << " rho " << rho;
    }
    for (double rho : {kW + kR, 0.8, 2.0, 10.0}) {
      EXPECT_NEAR(RootAlongZ(m, rho * std::cos(2.0), rho * std::sin(2.0), 0.01, 0.39), kRc / 2,
                  1e-12)
          << "flare " << flare << " rho " << rho;
    }
  }
}

// Above the plane the skeleton form and the project's coleman_features over the half-space
// z <= 0 are the same function (the latter's nearest point by central differences: 1e-8).
TEST(ColemanNotesForm, AgreesWithTheColemanFeaturesNodeOverAHalfSpace) {
  Model half_space;
  const int core = half_space.AddPrimitive(NodeType::kPlane, {0, 0, 1, 0});
  half_space.AddColemanFeatures(core, kRc, {0, 0, kRc / 2, kW, kD, kR, 0.5});
  const Model notes = NotesModel(0.5);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1.5, 1.5), h(0.01, 2.0);
  for (int n = 0; n < 3000; ++n) {
    const Vec x(u(rng), u(rng), h(rng));
    EXPECT_NEAR(notes.Value(x), half_space.Value(x), 1e-8) << x.transpose();
  }
}

// The triangle skeleton's distance: the minimum over a dense barycentric grid of the triangle
// is an upper bound within the grid's spacing (and never below the exact distance).
TEST(ColemanNotesForm, TriangleSkeletonDistanceAgainstBruteForce) {
  const Vec a(-0.6, -0.3, 0.1), b(0.7, -0.2, -0.2), c(0.1, 0.8, 0.3);
  Model m;
  m.AddSkeletonOffset(SkeletonKind::kTriangles,
                      {a.x(), a.y(), a.z(), b.x(), b.y(), b.z(), c.x(), c.y(), c.z()}, 0.25);
  const int steps = 600;
  std::vector<Vec> grid;
  for (int i = 0; i <= steps; ++i)
    for (int j = 0; i + j <= steps; ++j)
      grid.push_back(a + (double(i) / steps) * (b - a) + (double(j) / steps) * (c - a));
  const double spacing = 1.5 / steps;  // longest edge / steps bounds the distance to the grid
  std::mt19937 rng(6);
  std::uniform_real_distribution<double> u(-1.5, 1.5);
  for (int n = 0; n < 200; ++n) {
    const Vec x(u(rng), u(rng), u(rng));
    double brute = 1e300;
    for (const Vec& g : grid) brute = std::min(brute, (x - g).norm());
    const double exact = m.Value(x) + 0.25;
    EXPECT_LE(exact, brute + 1e-12) << x.transpose();
    EXPECT_GE(exact, brute - spacing) << x.transpose();
  }
}

// A smoothstep falloff s(t; a, b) written from Coleman's App. A for this test.
double S(double t, double a, double b) {
  if (t <= a) return 1.0;
  if (t >= b) return 0.0;
  const double v = (t - a) / (b - a);
  return 1.0 - (3 * v * v - 2 * v * v * v);
}

// Core = the segment from (-5, 0, 0) to (5, 0, 0) (a line near the origin), feature at
// f = (0, 0, R_C/2): c(f) = 0, u = +z. At x = (0, y, z): p1 = (0, y, 0), |p1 - c(f)| = |y|;
// p2 = c(x) = 0, |p2 - c(f)| = 0; d = sqrt(y^2 + z^2). So flare 0 gives k = s(|y|; W, W + R)
// and flare 1 gives k = 1, and f = 1/2 - max(i, k j + (1 - k) i).
TEST(ColemanNotesForm, FlareZeroUsesTheTangentPlaneAndFlareOneTheNearestCorePoint) {
  for (double flare : {0.0, 1.0}) {
    Model m;
    m.AddSkeletonOffsetWithFeatures(SkeletonKind::kSegments, {-5, 0, 0, 5, 0, 0}, kRc,
                                    {0, 0, kRc / 2, kW, kD, kR, flare});
    for (const Vec& x :
         {Vec(0, 0.35, 0.9), Vec(0, 0.42, 0.8), Vec(0, 0.2, 1.0), Vec(0, 0.6, 0.6)}) {
      const double d = std::hypot(x.y(), x.z());
      const double i = S(d, 0, kRc), j = S(d, kRc + kD + kW, kRc + kD + kW + kR);
      const double k = flare == 0.0 ? S(std::abs(x.y()), kW, kW + kR) : 1.0;
      const double expected = 0.5 - std::max(i, k * j + (1 - k) * i);
      EXPECT_NEAR(m.Value(x), expected, 1e-14) << "flare " << flare << " at " << x.transpose();
    }
  }
  // The two differ where the tangent-plane distance leaves the plateau and the core's does not.
  Model a, b;
  a.AddSkeletonOffsetWithFeatures(SkeletonKind::kSegments, {-5, 0, 0, 5, 0, 0}, kRc,
                                  {0, 0, kRc / 2, kW, kD, kR, 0.0});
  b.AddSkeletonOffsetWithFeatures(SkeletonKind::kSegments, {-5, 0, 0, 5, 0, 0}, kRc,
                                  {0, 0, kRc / 2, kW, kD, kR, 1.0});
  EXPECT_GT(std::abs(a.Value(Vec(0, 0.42, 0.8)) - b.Value(Vec(0, 0.42, 0.8))), 0.05);
}

// With the skeleton's exact nearest point there is no differencing inside f: Jets agree with
// central differences to 1e-7 on a curved core (a polyline), flare 0.3, on the ramps.
TEST(ColemanNotesForm, JetDerivativesExactOnACurvedCore) {
  Model m;
  m.AddSkeletonOffsetWithFeatures(SkeletonKind::kPolyline, {-2, 0, 0, 0, 0, 0.3, 2, 0, 0}, kRc,
                                  {0.1, 0.0, 0.45, kW, kD, kR, 0.3});
  ceres::DynamicAutoDiffCostFunction<ModelValueCost, 4> cost(new ModelValueCost{&m});
  cost.AddParameterBlock(static_cast<int>(m.parameters().size()));
  cost.AddParameterBlock(3);
  cost.SetNumResiduals(1);
  int checked = 0;
  for (const Vec& x : {Vec(0.15, 0.1, 1.25), Vec(0.2, 0.45, 1.0), Vec(1.2, 0.1, 0.35),
                       Vec(-0.6, 0.05, 0.55), Vec(0.05, 0.2, 1.3)}) {
    const auto report =
        testsupport::CompareWithCentralDifferences(cost, {m.parameters(), {x.x(), x.y(), x.z()}});
    EXPECT_LT(report.worst_error, 1e-7) << x.transpose() << report.detail;
    checked += report.largest_entry > 0.1;
  }
  EXPECT_GE(checked, 4);  // most points on a ramp (not flat)
}

TEST(ColemanNotesForm, RefusalsNameTheJsonPath) {
  json bad = json::parse(kNotesModel);
  bad["root"]["features"][0]["flare"] = 1.5;
  try {
    ModelFromJson(bad);
    FAIL() << "flare 1.5 accepted";
  } catch (const ModelFormatError& e) {
    EXPECT_NE(std::string(e.what()).find("root.features[0].flare"), std::string::npos) << e.what();
  }
  bad = json::parse(kNotesModel);
  bad["root"]["features"] = json::array();
  EXPECT_THROW(ModelFromJson(bad), ModelFormatError);
  bad = json::parse(kNotesModel);
  bad["root"]["skeleton"]["triangles"][0].erase(2);
  try {
    ModelFromJson(bad);
    FAIL() << "a two-corner triangle accepted";
  } catch (const ModelFormatError& e) {
    EXPECT_NE(std::string(e.what()).find("root.skeleton.triangles[0]"), std::string::npos)
        << e.what();
  }
  json fixed = json::parse(kNotesModel);
  fixed["root"]["fixed"] = {"skeleton", "features"};
  EXPECT_NO_THROW(ModelFromJson(fixed));
}

}  // namespace
}  // namespace implicitfit
