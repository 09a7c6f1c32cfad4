// Coleman's features (docs/maths.md CO-2): the plateau closed form (core z <= 0, a point feature
// above the origin, iso 1/2): the zero set is z = R_C + D + W + R/2 for rho <= W and z = R_C/2
// for rho >= W + R, found by bisection along z to 1e-12, for flare 0, 1/2 and 1 (no effect on a
// planar core); the falloff's closed form; Jet derivatives against central differences; JSON.
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
using testsupport::ModelValueCost;
using testsupport::RootAlongZ;
constexpr double kRc = 0.4, kW = 0.3, kD = 0.25, kR = 0.2;

Model Plateau(double flare) {
  Model m;
  const int core = m.AddPrimitive(NodeType::kPlane, {0, 0, 1, 0});  // core z <= 0
  m.AddColemanFeatures(core, kRc, {0, 0, kRc / 2, kW, kD, kR, flare});
  return m;
}

TEST(ColemanFeatures, FalloffIsTheSmoothstepOfAppendixA) {
  EXPECT_EQ(ColemanFeatures::Falloff(-1.0, 0.0, 2.0), 1.0);
  EXPECT_EQ(ColemanFeatures::Falloff(3.0, 0.0, 2.0), 0.0);
  EXPECT_DOUBLE_EQ(ColemanFeatures::Falloff(1.0, 0.0, 2.0), 0.5);
  const double u = 0.25;  // 1 - (3u^2 - 2u^3)
  EXPECT_NEAR(ColemanFeatures::Falloff(0.5, 0.0, 2.0), 1 - (3 * u * u - 2 * u * u * u), 1e-15);
}

TEST(ColemanFeatures, PlateauClosedFormForEveryFlare) {
  for (double flare : {0.0, 0.5, 1.0}) {
    const Model m = Plateau(flare);
    for (double rho : {0.0, 0.1, 0.2, kW}) {
      const double c = std::cos(0.7), s = std::sin(0.7);
      EXPECT_NEAR(RootAlongZ(m, rho * c, rho * s, 0.5, 2.0), kRc + kD + kW + kR / 2, 1e-12)
          << "flare " << flare << " rho " << rho;
    }
    for (double rho : {kW + kR, 0.8, 2.0}) {
      EXPECT_NEAR(RootAlongZ(m, rho, 0.0, 0.01, 0.39), kRc / 2, 1e-12)
          << "flare " << flare << " rho " << rho;
    }
  }
  // Between the two the flare still changes nothing: p1 = p2 on a planar core.
  const Model a = Plateau(0.0), b = Plateau(1.0);
  std::mt19937 rng(2);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int n = 0; n < 2000; ++n) {
    const Vec x(u(rng), u(rng), 1.5 * u(rng) + 0.5);
    EXPECT_NEAR(a.Value(x), b.Value(x), 1e-8) << x.transpose();
  }
}

TEST(ColemanFeatures, JetDerivativesAgreeWithCentralDifferencesOnTheRamps) {
  const Model m = Plateau(0.5);
  ceres::DynamicAutoDiffCostFunction<ModelValueCost, 4> cost(new ModelValueCost{&m});
  cost.AddParameterBlock(static_cast<int>(m.parameters().size()));
  cost.AddParameterBlock(3);
  cost.SetNumResiduals(1);
  // On the plateau's ramp (k = 1, j mid-ramp), on the feature's side ramp (k mid-ramp), and on
  // the offset's ramp far away: away from the falloffs' ends (C^1 only there). The closest core
  // point uses a central difference of the core (step 1e-6) inside f, so the test's own central
  // differences (step 1e-6) carry rounding noise ~ 1e-16 / (1e-6 * 1e-6) = 1e-4: the bound.
  for (const Vec& x : {Vec(0.1, 0.05, 1.04), Vec(0.4, 0.0, 0.6), Vec(1.2, -0.3, 0.21)}) {
    const auto report =
        testsupport::CompareWithCentralDifferences(cost, {m.parameters(), {x.x(), x.y(), x.z()}});
    EXPECT_LT(report.worst_error, 3e-4) << report.detail;
    EXPECT_GT(report.largest_entry, 0.1);
  }
}

TEST(ColemanFeatures, JsonRoundTripAndRefusals) {
  const Model m = Plateau(0.5);
  const nlohmann::json j = ModelToJson(m);
  EXPECT_EQ(j["root"]["type"], "coleman_features");
  EXPECT_EQ(j["root"]["features"][0]["width"], kW);
  const Model back = ModelFromJson(j);
  EXPECT_EQ(ModelToJson(back), j);
  for (double z : {0.1, 0.5, 1.0, 1.1})
    EXPECT_EQ(back.Value(Vec(0.2, 0.1, z)), m.Value(Vec(0.2, 0.1, z)));
  nlohmann::json bad = j;
  bad["root"]["features"][0]["flare"] = 1.5;
  try {
    ModelFromJson(bad);
    FAIL() << "flare 1.5 accepted";
  } catch (const std::exception& e) {
    EXPECT_NE(std::string(e.what()).find("root.features[0].flare"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace implicitfit
