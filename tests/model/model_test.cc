#include "model/model.h"

#include <ceres/ceres.h>
#include <gtest/gtest.h>

#include <random>

#include "oracle/li_phillips_oracle.h"
#include "support/derivative_check.h"

namespace implicitfit {
namespace {

using Vec = Eigen::Vector3d;

Model TwoSpheresUnion(int order, double delta, double eps) {
  Model m;
  const int a = m.AddPrimitive(NodeType::kSphere, {0, 0, 0, 1});
  const int b = m.AddPrimitive(NodeType::kSphere, {1.5, 0, 0, 1});
  m.AddOperator(NodeType::kUnion, {a, b}, delta, eps, order);
  return m;
}

TEST(Model, BlendMatchesTheOracleAtRandomPoints) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-2, 3);
  const double c0[3] = {0, 0, 0}, c1[3] = {1.5, 0, 0};
  for (int order = 0; order <= 4; ++order) {
    const Model m = TwoSpheresUnion(order, 0.4, 0.3);
    for (int i = 0; i < 200; ++i) {
      const double x[3] = {u(rng), u(rng), u(rng)};
      const double expected =
          oracle::Union(oracle::Sphere(c0, 1, x), oracle::Sphere(c1, 1, x), 0.4, 0.3, order);
      EXPECT_NEAR(m.Value(Vec(x[0], x[1], x[2])), expected, 1e-12);
    }
  }
}

TEST(Model, MoreThanTwoChildrenFoldLeftToRight) {
  Model m;
  const int a = m.AddPrimitive(NodeType::kSphere, {0, 0, 0, 1});
  const int b = m.AddPrimitive(NodeType::kSphere, {1, 0, 0, 1});
  const int c = m.AddPrimitive(NodeType::kPlane, {0, 0, 1, 0.2});
  m.AddOperator(NodeType::kDifference, {a, b, c}, 0.3, 0.2, 2);
  const double ca[3] = {0, 0, 0}, cb[3] = {1, 0, 0}, n[3] = {0, 0, 1};
  for (const Vec& p : {Vec(-0.5, 0.1, 0.1), Vec(0.2, 0.3, 0.5), Vec(0.4, -0.2, -0.3)}) {
    const double x[3] = {p.x(), p.y(), p.z()};
    const double ab =
        oracle::Difference(oracle::Sphere(ca, 1, x), oracle::Sphere(cb, 1, x), 0.3, 0.2, 2);
    EXPECT_NEAR(m.Value(p), oracle::Difference(ab, oracle::Plane(n, 0.2, x), 0.3, 0.2, 2), 1e-13);
  }
}

TEST(Model, GradientAgreesWithCentralDifferencesThroughBlends) {
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> u(-1.5, 2.5);
  for (int order = 1; order <= 4; ++order) {
    const Model m = TwoSpheresUnion(order, 0.5, 0.35);
    for (int i = 0; i < 100; ++i) {
      const Vec x(u(rng), u(rng), u(rng));
      const Vec g = m.Gradient(x);
      const double h = 1e-6;
      for (int k = 0; k < 3; ++k) {
        Vec xp = x, xm = x;
        xp[k] += h;
        xm[k] -= h;
        EXPECT_NEAR(g[k], (m.Value(xp) - m.Value(xm)) / (2 * h), 2e-6) << "order " << order;
      }
    }
  }
}

struct TreeCost {
  const Model* model;
  template <typename T>
  bool operator()(const T* params, const T* x, T* r) const {
    r[0] = model->Evaluate(params, x);
    return true;
  }
};

TEST(Model, JetDerivativesInDeltaAndEpsilonAgreeWithNumeric) {
  // The fitter differentiates w.r.t. delta and epsilon: the Jets must flow through the unit
  // step polynomials.
  const Model m = TwoSpheresUnion(3, 0.5, 0.35);
  ceres::AutoDiffCostFunction<TreeCost, 1, 10, 3> cost(new TreeCost{&m});
  std::mt19937 rng(2);
  std::uniform_real_distribution<double> u(-0.3, 0.3);
  int probed_in_blend = 0;
  for (int i = 0; i < 100; ++i) {
    const Vec x(0.75 + u(rng), u(rng) * 3, u(rng) * 3);
    const auto report =
        testsupport::CompareWithCentralDifferences(cost, {m.parameters(), {x.x(), x.y(), x.z()}});
    EXPECT_LT(report.worst_error, 1e-6) << report.detail;
    // Inside the blend zone f depends on delta: count such probes.
    Model moved = m;
    moved.mutable_parameters()[8] += 1e-3;
    if (std::abs(moved.Value(x) - m.Value(x)) > 1e-9) ++probed_in_blend;
  }
  EXPECT_GT(probed_in_blend, 10) << "the probes must reach the blend zone";
}

TEST(Model, ParameterNamesFollowTheTreeAndNodeNames) {
  Model m;
  const int a = m.AddPrimitive(NodeType::kSphere, {0, 0, 0, 1}, "ball");
  const int b = m.AddPrimitive(NodeType::kPlane, {0, 0, 1, 0});
  m.AddOperator(NodeType::kIntersection, {a, b}, 0.1, 0.05, 2);
  const std::vector<std::string> names = m.ParameterNames();
  ASSERT_EQ(names.size(), 10u);
  EXPECT_EQ(names[0], "ball.center[0]");
  EXPECT_EQ(names[3], "ball.radius");
  EXPECT_EQ(names[4], "root.children[1].normal[0]");
  EXPECT_EQ(names[7], "root.children[1].offset");
  EXPECT_EQ(names[8], "root.delta");
  EXPECT_EQ(names[9], "root.epsilon");
}

TEST(Model, BuildersRefuseWrongParameterCounts) {
  Model m;
  EXPECT_THROW(m.AddPrimitive(NodeType::kSphere, {0, 0, 0}), std::invalid_argument);
  EXPECT_THROW(m.AddPrimitive(NodeType::kUnion, {0, 0}), std::invalid_argument);
  EXPECT_THROW(m.AddOperator(NodeType::kUnion, {3}, 1, 1, 1), std::invalid_argument);
}

}  // namespace
}  // namespace implicitfit
