// The fit side of the primitive kinds' table (fit/primitive/fittable_primitives.h) and what the fitter
// derives from the field roles (fit/metrology/primitive_tangent.h), checked against independent facts:
// the parameter count of each evaluator, the rank of the distance Jacobian at many points (the
// number of parameters that shape the surface), the minimal-sample hypothesis reproducing an
// exact primitive, and the translation of the model's own f.
#include "fit/primitive/fittable_primitives.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <map>
#include <random>

#include "fit/primitive/primitive_fitter.h"
#include "fit/metrology/primitive_tangent.h"

namespace implicitfit {
namespace {

using Vec = Eigen::Vector3d;

// A generic primitive of each fittable kind (model/*.h layouts).
std::map<NodeType, std::vector<double>> Truths() {
  return {
      {NodeType::kPlane, {0.3, -0.2, 0.9, 0.4}},
      {NodeType::kSphere, {0.1, -0.2, 0.3, 0.7}},
      {NodeType::kCylinder, {0.1, 0.2, -0.1, 0.2, 0.1, 1.0, 0.5}},
      {NodeType::kCone, {0.1, 0.0, -0.5, 0.1, -0.2, 1.0, 0.5}},
      {NodeType::kTorus, {0.1, 0.1, 0.0, 0.0, 0.3, 1.0, 0.8, 0.25}},
  };
}

// Points on the surface: random starts (for the cone, inside its opening) projected by Newton
// steps x -= f grad f / |grad f|^2 on the model's own f (automatic differentiation, model/).
std::vector<Vec> SurfacePoints(NodeType kind, const std::vector<double>& p, int n, unsigned seed,
                               std::vector<Vec>* normals) {
  Model m;
  m.AddPrimitive(kind, p);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<Vec> x;
  normals->clear();
  while (static_cast<int>(x.size()) < n) {
    Vec y(u(rng), u(rng), u(rng));
    if (kind == NodeType::kCone) {  // apex + h a + a radial offset near the nappe
      const Vec a = Vec(p[3], p[4], p[5]).normalized();
      const Vec e = a.cross(y).normalized();
      const double h = 0.7 + 0.5 * u(rng);
      y = Vec(p[0], p[1], p[2]) + h * a + (1.0 + 0.2 * u(rng)) * h * std::tan(p[6]) * e;
    }
    for (int it = 0; it < 30; ++it) {
      double f;
      const Vec g = m.Gradient(y, &f);
      y -= f * g / g.squaredNorm();
    }
    double f;
    const Vec g = m.Gradient(y, &f);
    if (!(std::abs(f) < 1e-12) || g.norm() < 0.5) continue;
    x.push_back(y);
    normals->push_back(g.normalized());
  }
  return x;
}

TEST(FittablePrimitives, EvaluatorsMatchTheModelTable) {
  EXPECT_EQ(FittablePrimitives().size(), std::tuple_size_v<FittableEvaluators>);
  for (const FittablePrimitive& kind : FittablePrimitives()) {
    SCOPED_TRACE(NodeTypeName(kind.type));
    const int evaluator_parameters =
        VisitFittablePrimitive(kind.type, [](auto e) { return decltype(e)::kNumParameters; });
    EXPECT_EQ(evaluator_parameters, NumParametersOf(kind.type));
    EXPECT_EQ(FindFittablePrimitive(kind.type), &kind);
  }
  EXPECT_THROW(VisitFittablePrimitive(NodeType::kEllipsoid, [](auto) { return 0; }),
               std::invalid_argument);
  EXPECT_EQ(FindFittablePrimitive(NodeType::kQuadric), nullptr);
  EXPECT_EQ(FittableKindNames(), "plane, sphere, cylinder, cone, torus");
  NodeType k;
  for (const char* name : {"plane", "sphere", "cylinder", "cone", "torus"})
    EXPECT_TRUE(FittableKindFromName(name, &k)) << name;
  EXPECT_FALSE(FittableKindFromName("ellipsoid", &k));
}

// FreeParameterCount (from the roles) equals the rank of the Jacobian of the distances with
// respect to the parameters, stacked over many surface points: the number of parameter
// combinations that move the surface. The tangent basis has that many independent columns.
TEST(FittablePrimitives, FreeParameterCountIsTheRankOfTheDistanceJacobian) {
  for (const auto& [kind, p] : Truths()) {
    SCOPED_TRACE(NodeTypeName(kind));
    std::vector<Vec> normals;
    const std::vector<Vec> x = SurfacePoints(kind, p, 200, 11, &normals);
    const int P = static_cast<int>(p.size());
    Eigen::MatrixXd J(x.size(), P);
    std::vector<double> dp(P);
    for (size_t i = 0; i < x.size(); ++i) {
      PrimitiveSignedDistance(kind, p.data(), x[i].data(), dp.data());
      for (int j = 0; j < P; ++j) J(i, j) = dp[j];
    }
    Eigen::JacobiSVD<Eigen::MatrixXd> svd(J);
    const Eigen::VectorXd s = svd.singularValues();
    int rank = 0;
    for (int j = 0; j < s.size(); ++j) rank += s[j] > 1e-9 * s[0];
    EXPECT_EQ(FreeParameterCount(kind), rank);
    const Eigen::MatrixXd B = TangentBasis(kind, p);
    EXPECT_EQ(B.cols(), rank);
    Eigen::FullPivLU<Eigen::MatrixXd> lu(J * B);
    EXPECT_EQ(lu.rank(), rank);
  }
}

// The minimal-sample hypothesis of an exact sample is the primitive: every other surface point
// has |f| < 1e-7 under it.
TEST(FittablePrimitives, HypothesisFromAnExactSampleReproducesThePrimitive) {
  for (const auto& [kind, p] : Truths()) {
    SCOPED_TRACE(NodeTypeName(kind));
    const FittablePrimitive& entry = *FindFittablePrimitive(kind);
    std::vector<Vec> n;
    const std::vector<Vec> x = SurfacePoints(kind, p, entry.sample_size + 50, 21, &n);
    std::vector<double> h;
    ASSERT_TRUE(entry.from_sample(x.data(), n.data(), &h));
    ASSERT_EQ(static_cast<int>(h.size()), NumParametersOf(kind));
    Model m;
    m.AddPrimitive(kind, h);
    double worst = 0.0;
    for (size_t i = entry.sample_size; i < x.size(); ++i)
      worst = std::max(worst, std::abs(m.Value(x[i])));
    EXPECT_LT(worst, 1e-7);
  }
}

// TranslatePrimitive (by roles) moves the model's own f: f'(x + t) = f(x).
TEST(FittablePrimitives, TranslationByRolesMovesTheSurface) {
  const Vec t(100.0, -250.0, 42.0);
  for (const auto& [kind, p] : Truths()) {
    SCOPED_TRACE(NodeTypeName(kind));
    std::vector<double> moved = p;
    TranslatePrimitive(kind, t, &moved);
    Model a, b;
    a.AddPrimitive(kind, p);
    b.AddPrimitive(kind, moved);
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> u(-1.5, 1.5);
    for (int i = 0; i < 30; ++i) {
      const Vec x(u(rng), u(rng), u(rng));
      EXPECT_NEAR(b.Value(x + t), a.Value(x), 1e-10);
    }
  }
}

}  // namespace
}  // namespace implicitfit
