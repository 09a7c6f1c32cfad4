// One property suite run for every primitive kind (in the manner of manif's typed tests):
// zero set on points sampled from the kind's parametric form (written here, independently of
// the evaluator), gradient equal to the outward unit normal there, |grad f| = 1 off the surface
// where f is a true distance, f(p + h n) = h along the normal, and analytic (Jet) derivatives
// against central finite differences (tests/support/derivative_check.h).
#include <ceres/ceres.h>
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "model/model.h"
#include "support/derivative_check.h"

namespace implicitfit {
namespace {

using Vec = Eigen::Vector3d;

struct Frame {  // orthonormal frame around an axis a
  Vec a, e1, e2;
  explicit Frame(const Vec& axis) : a(axis.normalized()) {
    e1 = a.unitOrthogonal();
    e2 = a.cross(e1);
  }
};

// A sampled surface point and the outward unit normal there.
struct SurfacePoint {
  Vec x, n;
};

struct PlaneKind {
  static constexpr NodeType kType = NodeType::kPlane;
  static constexpr bool kTrueDistance = true;
  static std::vector<double> Params() { return {0.3, -0.4, 0.8660254037844386, 0.7}; }
  static SurfacePoint Sample(std::mt19937& rng) {
    std::uniform_real_distribution<double> u(-3, 3);
    const Vec n = Vec(0.3, -0.4, 0.8660254037844386).normalized();
    const Frame f(n);
    return {n * 0.7 / Vec(0.3, -0.4, 0.8660254037844386).norm() + u(rng) * f.e1 + u(rng) * f.e2, n};
  }
};

struct SphereKind {
  static constexpr NodeType kType = NodeType::kSphere;
  static constexpr bool kTrueDistance = true;
  static std::vector<double> Params() { return {1.0, -2.0, 0.5, 1.7}; }
  static SurfacePoint Sample(std::mt19937& rng) {
    std::normal_distribution<double> g;
    const Vec d = Vec(g(rng), g(rng), g(rng)).normalized();
    return {Vec(1.0, -2.0, 0.5) + 1.7 * d, d};
  }
};

struct CylinderKind {
  static constexpr NodeType kType = NodeType::kCylinder;
  static constexpr bool kTrueDistance = true;
  static std::vector<double> Params() { return {0.5, 0.2, -1.0, 1.0, 2.0, 0.5, 0.8}; }
  static SurfacePoint Sample(std::mt19937& rng) {
    std::uniform_real_distribution<double> u(-3, 3), th(0, 2 * M_PI);
    const Frame f(Vec(1.0, 2.0, 0.5));
    const double theta = th(rng);
    const Vec radial = std::cos(theta) * f.e1 + std::sin(theta) * f.e2;
    return {Vec(0.5, 0.2, -1.0) + u(rng) * f.a + 0.8 * radial, radial};
  }
};

struct ConeKind {
  static constexpr NodeType kType = NodeType::kCone;
  static constexpr bool kTrueDistance = true;
  static constexpr double kAlpha = 0.45;
  static std::vector<double> Params() { return {0.1, 0.2, 0.3, -0.3, 0.4, 1.0, kAlpha}; }
  static SurfacePoint Sample(std::mt19937& rng) {
    std::uniform_real_distribution<double> s(0.2, 4.0), th(0, 2 * M_PI);
    const Frame f(Vec(-0.3, 0.4, 1.0));
    const double theta = th(rng);
    const Vec radial = std::cos(theta) * f.e1 + std::sin(theta) * f.e2;
    const Vec generator = std::cos(kAlpha) * f.a + std::sin(kAlpha) * radial;
    const Vec normal = std::cos(kAlpha) * radial - std::sin(kAlpha) * f.a;
    return {Vec(0.1, 0.2, 0.3) + s(rng) * generator, normal};
  }
};

struct TorusKind {
  static constexpr NodeType kType = NodeType::kTorus;
  static constexpr bool kTrueDistance = true;
  static std::vector<double> Params() { return {-1.0, 0.0, 2.0, 0.0, 1.0, 1.0, 2.0, 0.6}; }
  static SurfacePoint Sample(std::mt19937& rng) {
    std::uniform_real_distribution<double> th(0, 2 * M_PI);
    const Frame f(Vec(0.0, 1.0, 1.0));
    const double theta = th(rng), phi = th(rng);
    const Vec radial = std::cos(theta) * f.e1 + std::sin(theta) * f.e2;
    const Vec normal = std::cos(phi) * radial + std::sin(phi) * f.a;
    return {Vec(-1.0, 0.0, 2.0) + 2.0 * radial + 0.6 * normal, normal};
  }
};

struct EllipsoidKind {
  static constexpr NodeType kType = NodeType::kEllipsoid;
  static constexpr bool kTrueDistance = false;
  static Frame F() { return Frame(Vec(1.0, 1.0, 0.0)); }
  static std::vector<double> Params() {
    const Frame f = F();
    return {0.5, 0.5, 0.5, 2.0, 1.2, 0.7, f.a.x(), f.a.y(), f.a.z(), f.e1.x(), f.e1.y(), f.e1.z()};
  }
  static SurfacePoint Sample(std::mt19937& rng) {
    std::normal_distribution<double> g;
    const Vec y = Vec(g(rng), g(rng), g(rng)).normalized();
    const Frame f = F();
    const Vec axes[3] = {f.a, f.e1, f.a.cross(f.e1)};
    const double r[3] = {2.0, 1.2, 0.7};
    Vec x(0.5, 0.5, 0.5), n = Vec::Zero();
    for (int i = 0; i < 3; ++i) {
      x += r[i] * y[i] * axes[i];
      n += y[i] / r[i] * axes[i];
    }
    return {x, n.normalized()};
  }
};

struct QuadricKind {  // hyperboloid of one sheet x^2/4 + y^2 - z^2/2.25 - 1 = 0
  static constexpr NodeType kType = NodeType::kQuadric;
  static constexpr bool kTrueDistance = false;
  static std::vector<double> Params() { return {0.25, 1.0, -1.0 / 2.25, 0, 0, 0, 0, 0, 0, -1.0}; }
  static SurfacePoint Sample(std::mt19937& rng) {
    std::uniform_real_distribution<double> th(0, 2 * M_PI), v(-1.0, 1.0);
    const double u = th(rng), w = v(rng);
    const Vec x(2.0 * std::cosh(w) * std::cos(u), std::cosh(w) * std::sin(u), 1.5 * std::sinh(w));
    return {x, Vec(x.x() / 4.0, x.y(), -x.z() / 2.25).normalized()};
  }
};

template <typename Kind>
class PrimitiveProperties : public ::testing::Test {
 protected:
  PrimitiveProperties() { model_.AddPrimitive(Kind::kType, Kind::Params()); }
  Model model_;
  std::mt19937 rng_{1234};
};

using Kinds = ::testing::Types<PlaneKind, SphereKind, CylinderKind, ConeKind, TorusKind,
                               EllipsoidKind, QuadricKind>;
TYPED_TEST_SUITE(PrimitiveProperties, Kinds);

TYPED_TEST(PrimitiveProperties, SampledSurfacePointsAreOnTheZeroSet) {
  for (int i = 0; i < 200; ++i) {
    const SurfacePoint s = TypeParam::Sample(this->rng_);
    EXPECT_NEAR(this->model_.Value(s.x), 0.0, 1e-12);
  }
}

TYPED_TEST(PrimitiveProperties, GradientIsTheOutwardUnitNormalOnTheSurface) {
  for (int i = 0; i < 200; ++i) {
    const SurfacePoint s = TypeParam::Sample(this->rng_);
    const Vec g = this->model_.Gradient(s.x);
    EXPECT_NEAR((g - s.n).norm(), 0.0, 1e-9) << "at " << s.x.transpose();
  }
}

TYPED_TEST(PrimitiveProperties, ValueAlongTheNormalIsTheOffset) {
  // For a true distance f(p + h n) = h for small |h| on either side; for the first-order
  // distances (ellipsoid, quadric) only to first order: |f - h| = O(h^2).
  for (int i = 0; i < 100; ++i) {
    const SurfacePoint s = TypeParam::Sample(this->rng_);
    for (double h : {-0.05, -0.01, 0.01, 0.05}) {
      const double f = this->model_.Value(s.x + h * s.n);
      if (TypeParam::kTrueDistance)
        EXPECT_NEAR(f, h, 1e-12);
      else
        EXPECT_NEAR(f, h, 40 * h * h);
      EXPECT_EQ(f > 0, h > 0) << "sign convention: f > 0 outside";
    }
  }
}

TYPED_TEST(PrimitiveProperties, TrueDistancesHaveUnitGradientEverywhere) {
  if (!TypeParam::kTrueDistance)
    GTEST_SKIP() << "first-order distance: |grad f| = 1 on the surface only";
  std::uniform_real_distribution<double> u(-4, 4);
  for (int i = 0; i < 300; ++i) {
    const Vec x(u(this->rng_), u(this->rng_), u(this->rng_));
    EXPECT_NEAR(this->model_.Gradient(x).norm(), 1.0, 1e-9) << x.transpose();
  }
}

// f as a Ceres cost of (parameters, point), so the Jet derivatives of both blocks can be
// compared against central differences.
template <typename Kind>
struct ValueCost {
  const Model* model;
  template <typename T>
  bool operator()(const T* params, const T* x, T* residual) const {
    residual[0] = model->Evaluate(params, x);
    return true;
  }
};

TYPED_TEST(PrimitiveProperties, JetDerivativesAgreeWithNumericDifferentiation) {
  constexpr int kParams = static_cast<int>(TypeParam::kType == NodeType::kPlane       ? 4
                                           : TypeParam::kType == NodeType::kSphere    ? 4
                                           : TypeParam::kType == NodeType::kTorus     ? 8
                                           : TypeParam::kType == NodeType::kEllipsoid ? 12
                                           : TypeParam::kType == NodeType::kQuadric   ? 10
                                                                                      : 7);
  ASSERT_EQ(kParams, NumParametersOf(TypeParam::kType));
  ceres::AutoDiffCostFunction<ValueCost<TypeParam>, 1, kParams, 3> cost(
      new ValueCost<TypeParam>{&this->model_});
  std::uniform_real_distribution<double> u(-0.3, 0.3);
  for (int i = 0; i < 50; ++i) {
    const SurfacePoint s = TypeParam::Sample(this->rng_);
    const Vec x = s.x + u(this->rng_) * s.n;
    const auto report = testsupport::CompareWithCentralDifferences(
        cost, {TypeParam::Params(), {x.x(), x.y(), x.z()}});
    EXPECT_LT(report.worst_error, 1e-7) << report.detail;
    EXPECT_GT(report.largest_entry, 0.1);
  }
}

TEST(Cone, PointsBehindTheApexAreOutsideAtTheirDistanceToTheApex) {
  Model m;
  m.AddPrimitive(NodeType::kCone, {0, 0, 0, 0, 0, 1, 0.5});
  const Vec behind(0.1, 0.0, -2.0);
  EXPECT_NEAR(m.Value(behind), behind.norm(), 1e-14);
  EXPECT_LT(m.Value(Vec(0, 0, 1)), 0.0);  // on the axis, inside the opening
  EXPECT_NEAR(m.Value(Vec(0, 0, 1)), -std::sin(0.5), 1e-14);
}

TEST(Cylinder, AxisLengthDoesNotMatter) {
  Model a, b;
  a.AddPrimitive(NodeType::kCylinder, {0, 0, 0, 0, 0, 1, 1});
  b.AddPrimitive(NodeType::kCylinder, {0, 0, 0, 0, 0, 7.5, 1});
  for (const Vec& x : {Vec(3, 4, 1), Vec(0.2, 0.1, -5)}) EXPECT_NEAR(a.Value(x), b.Value(x), 1e-15);
  EXPECT_NEAR(a.Value(Vec(3, 4, 1)), 4.0, 1e-15);
}

TEST(Quadric, PositiveScalingDoesNotChangeF) {
  Model a, b;
  std::vector<double> q = QuadricKind::Params(), q3 = q;
  for (double& c : q3) c *= 3.0;
  a.AddPrimitive(NodeType::kQuadric, q);
  b.AddPrimitive(NodeType::kQuadric, q3);
  for (const Vec& x : {Vec(3, 4, 1), Vec(0.2, 0.1, -5)}) EXPECT_NEAR(a.Value(x), b.Value(x), 1e-13);
}

TEST(Quadric, StaysFiniteWhereItsGradientVanishes) {
  Model m;  // sphere x^2 + y^2 + z^2 - 1 has grad q = 0 at the origin
  m.AddPrimitive(NodeType::kQuadric, {1, 1, 1, 0, 0, 0, 0, 0, 0, -1});
  const double f = m.Value(Vec::Zero());
  EXPECT_TRUE(std::isfinite(f));
  EXPECT_LT(f, 0.0);
  EXPECT_TRUE(m.Gradient(Vec::Zero()).allFinite());
}

}  // namespace
}  // namespace implicitfit
