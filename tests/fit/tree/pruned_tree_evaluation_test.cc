// fit/tree/pruned_tree_evaluation.h against Model::Evaluate: the same value and the same derivatives
// w.r.t. every parameter (Jets seeded with one unit vector per parameter), to rounding, on
// trees with every operator, smoothing and order, nested, at points inside blend bands and far
// from them (where most children are skipped).
#include "fit/tree/pruned_tree_evaluation.h"

#include "fit/tree/tree_parameters.h"

#include <ceres/jet.h>
#include <gtest/gtest.h>

#include <random>

namespace implicitfit {
namespace {

using Vec = Eigen::Vector3d;
constexpr int kMaxParameters = 64;
using Jet = ceres::Jet<double, kMaxParameters>;

// The design builder's shape: an ellipsoid base and six planes of a box, one smooth
// intersection (order 3).
Model DesignLike() {
  Model m;
  std::vector<int> c = {
      m.AddPrimitive(NodeType::kEllipsoid, {0.1, -0.1, 0.05, 0.9, 0.7, 0.6, 1, 0, 0, 0, 1, 0})};
  const double h[3] = {0.5, 0.4, 0.3};
  for (int k = 0; k < 3; ++k)
    for (double s : {-1.0, 1.0}) {
      std::vector<double> p = {0, 0, 0, h[k]};
      p[k] = s;
      c.push_back(m.AddPrimitive(NodeType::kPlane, p));
    }
  m.AddOperator(NodeType::kIntersection, c, 0.06, 0.03, 3);
  return m;
}

// difference(union(sphere, sphere, cylinder) [order 2], intersection(box, sphere) [sharp]).
Model Nested() {
  Model m;
  const int a = m.AddPrimitive(NodeType::kSphere, {-0.3, 0, 0, 0.5});
  const int b = m.AddPrimitive(NodeType::kSphere, {0.35, 0.1, 0, 0.45});
  const int cyl = m.AddPrimitive(NodeType::kCylinder, {0, 0, 0, 0, 0, 1, 0.15});
  const int u = m.AddOperator(NodeType::kUnion, {a, b, cyl}, 0.1, 0.07, 2);
  const int box = m.AddPrimitive(NodeType::kBox, {0, 0, 0.4, 1, 0, 0, 0, 0.3, 0.3, 0.2});
  const int s = m.AddPrimitive(NodeType::kSphere, {0, 0, 0.45, 0.3});
  const int i = m.AddOperator(NodeType::kIntersection, {box, s}, 0.05, 0.05, 0);
  m.AddOperator(NodeType::kDifference, {u, i}, 0.08, 0.04, 3);
  return m;
}

// A convex-smoothing intersection of four planes and a sphere, inside a union with a sphere.
Model ConvexSmoothing() {
  Model m;
  std::vector<int> c;
  for (int k = 0; k < 4; ++k) {
    const double a = k * M_PI / 2;
    c.push_back(m.AddPrimitive(NodeType::kPlane, {std::cos(a), std::sin(a), 0.2, 0.4}));
  }
  c.push_back(m.AddPrimitive(NodeType::kSphere, {0, 0, 0, 0.6}));
  const int i = m.AddOperator(NodeType::kIntersection, c, 0.1, 0.1, 3);
  m.mutable_nodes()[i].smoothing = BlendSmoothing::kConvex;
  const int s = m.AddPrimitive(NodeType::kSphere, {0.5, 0.5, 0.3, 0.25});
  m.AddOperator(NodeType::kUnion, {i, s}, 0.05, 0.02, 4);
  return m;
}

void ExpectSameAsModelEvaluate(const Model& m, int seed) {
  const std::vector<double>& p = m.parameters();
  ASSERT_LE(p.size(), static_cast<size_t>(kMaxParameters));
  std::vector<Jet> pj(p.size());
  for (size_t i = 0; i < p.size(); ++i) pj[i] = Jet(p[i], static_cast<int>(i));
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1.2, 1.2);
  for (int n = 0; n < 3000; ++n) {
    const double xd[3] = {u(rng), u(rng), u(rng)};
    const Jet xj[3] = {Jet(xd[0]), Jet(xd[1]), Jet(xd[2])};
    const Jet full = m.Evaluate(pj.data(), xj);
    const Jet pruned = PrunedEvaluate(m, pj.data(), p.data(), xj, xd);
    const double scale = 1.0 + std::abs(full.a);
    ASSERT_NEAR(pruned.a, full.a, 1e-14 * scale) << xd[0] << " " << xd[1] << " " << xd[2];
    for (size_t i = 0; i < p.size(); ++i)
      ASSERT_NEAR(pruned.v[i], full.v[i], 1e-12 * (1.0 + full.v.cwiseAbs().maxCoeff()))
          << "parameter " << i << " at " << xd[0] << " " << xd[1] << " " << xd[2];
    // And on doubles.
    ASSERT_NEAR(PrunedEvaluate(m, p.data(), p.data(), xd, xd), m.Value(Vec(xd[0], xd[1], xd[2])),
                1e-14 * scale);
  }
}

TEST(PrunedTreeEvaluation, DesignLikeIntersection) { ExpectSameAsModelEvaluate(DesignLike(), 1); }
TEST(PrunedTreeEvaluation, NestedOperatorsOfEveryKind) { ExpectSameAsModelEvaluate(Nested(), 2); }
TEST(PrunedTreeEvaluation, ConvexSmoothing) { ExpectSameAsModelEvaluate(ConvexSmoothing(), 3); }

// With every primitive's fields fixed (the blend refit of `reconstruct`), the constant
// subtrees are the leaves, and evaluating them once in double (the `constant` flags) gives the
// same value and the same derivatives w.r.t. the free parameters (the operators' delta and
// epsilon) as Model::Evaluate on Jets.
TEST(PrunedTreeEvaluation, ConstantSubtreesOfFixedPrimitivesChangeNothing) {
  Model m = Nested();
  for (ModelNode& node : m.mutable_nodes()) {
    if (IsOperator(node.type)) continue;
    for (const ParameterField& field : ParameterFieldsOf(node.type))
      node.fixed.push_back(field.name);
  }
  const std::vector<char> constant = TreeParameters(m).ConstantSubtrees(m);
  ASSERT_EQ(constant.size(), m.nodes().size());
  for (size_t i = 0; i < m.nodes().size(); ++i)
    EXPECT_EQ(constant[i] != 0, !IsOperator(m.nodes()[i].type)) << "node " << i;
  const std::vector<double>& p = m.parameters();
  std::vector<Jet> pj(p.size());
  std::vector<bool> free(p.size(), false);
  for (const ModelNode& node : m.nodes())
    if (IsOperator(node.type))
      for (int k = 0; k < node.num_parameters; ++k) free[node.first_parameter + k] = true;
  for (size_t i = 0; i < p.size(); ++i)
    pj[i] = free[i] ? Jet(p[i], static_cast<int>(i)) : Jet(p[i]);
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> u(-1.2, 1.2);
  for (int n = 0; n < 3000; ++n) {
    const double xd[3] = {u(rng), u(rng), u(rng)};
    const Jet xj[3] = {Jet(xd[0]), Jet(xd[1]), Jet(xd[2])};
    const Jet full = m.Evaluate(pj.data(), xj);
    const Jet pruned = PrunedEvaluate(m, pj.data(), p.data(), xj, xd, constant.data());
    ASSERT_NEAR(pruned.a, full.a, 1e-14 * (1.0 + std::abs(full.a)));
    for (size_t i = 0; i < p.size(); ++i)
      ASSERT_NEAR(pruned.v[i], full.v[i], 1e-12 * (1.0 + full.v.cwiseAbs().maxCoeff()))
          << "parameter " << i << " at " << xd[0] << " " << xd[1] << " " << xd[2];
  }
}

}  // namespace
}  // namespace implicitfit
