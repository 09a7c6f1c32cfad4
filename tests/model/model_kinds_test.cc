// The typed property suite (as tests/model/primitives_test.cc, manif style) for the node kinds
// of issue 16: box, paraboloid, blobs, skeleton offsets, soft partitions (grid, sequence). Each
// kind builds its model and samples surface points from its own parametric form (written here,
// independently of the evaluator):
//   zero set on the sampled points, grad f parallel to the outward normal there (and unit for
//   distances), f(p + h n) = h along the normal for exact distances, Jet derivatives w.r.t. every
//   parameter and x against central differences, and the JSON round trip.
#include <ceres/ceres.h>
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "model/model.h"
#include "model/model_json.h"
#include "support/derivative_check.h"

namespace implicitfit {
namespace {

using Vec = Eigen::Vector3d;

struct SurfacePoint {
  Vec x, n;
};

// Box: centre (0.3, -0.2, 0.5), half sizes (1.2, 0.7, 0.4), axes a rotation of 35 degrees about
// (1, 2, 2)/3. Points on a random face, at least `margin` from its edges (so that the offset
// h n of the along-normal test stays nearest to that face).
struct BoxKind {
  static constexpr bool kTrueDistance = true;
  static constexpr double kMargin = 0.06;
  static Eigen::Matrix3d Rotation() {
    return Eigen::AngleAxisd(35.0 * M_PI / 180.0, Vec(1, 2, 2) / 3.0).toRotationMatrix();
  }
  static Model Build() {
    const Eigen::Quaterniond q(Rotation());
    Model m;
    m.AddPrimitive(NodeType::kBox, {0.3, -0.2, 0.5, q.w(), q.x(), q.y(), q.z(), 1.2, 0.7, 0.4});
    return m;
  }
  static SurfacePoint Sample(std::mt19937& rng) {
    const Vec h(1.2, 0.7, 0.4);
    std::uniform_int_distribution<int> face(0, 5);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    const int f = face(rng), axis = f / 2;
    const double side = f % 2 ? 1.0 : -1.0;
    Vec y;
    for (int k = 0; k < 3; ++k) y[k] = u(rng) * (h[k] - kMargin);
    y[axis] = side * h[axis];
    const Eigen::Matrix3d r = Rotation();
    return {Vec(0.3, -0.2, 0.5) + r * y, side * r.col(axis)};
  }
};

// Paraboloid: vertex P, axis n, curvature 0.8; points P + w - (kappa / 2) |w|^2 n, normal
// n + kappa w (normalised), |w| <= 1.2.
struct ParaboloidKind {
  static constexpr bool kTrueDistance = false;
  static constexpr double kKappa = 0.8;
  static Vec P() { return Vec(0.2, 0.1, -0.3); }
  static Vec N() { return Vec(0.3, -0.5, 1.0).normalized(); }
  static Model Build() {
    Model m;
    m.AddPrimitive(NodeType::kParaboloid, {0.2, 0.1, -0.3, 0.3, -0.5, 1.0, kKappa});
    return m;
  }
  static SurfacePoint Sample(std::mt19937& rng) {
    std::uniform_real_distribution<double> r(0.0, 1.2), th(0, 2 * M_PI);
    const Vec n = N(), e1 = n.unitOrthogonal(), e2 = n.cross(e1);
    const double rho = r(rng), theta = th(rng);
    const Vec w = rho * (std::cos(theta) * e1 + std::sin(theta) * e2);
    return {P() + w - 0.5 * kKappa * rho * rho * n, (n + kKappa * w).normalized()};
  }
};

// One Gaussian blob (a = 3, b = 2, T = 1.2): the sphere R = sqrt(ln(a / T) / b), normal radial.
struct GaussianBlobKind {
  static constexpr bool kTrueDistance = false;
  static Model Build() {
    Model m;
    m.AddBlobs(BlobKernel::kGaussian, 0, {0.2, -0.1, 0.4}, {3.0}, {2.0}, 1.2);
    return m;
  }
  static SurfacePoint Sample(std::mt19937& rng) {
    std::normal_distribution<double> g;
    const Vec d = Vec(g(rng), g(rng), g(rng)).normalized();
    return {Vec(0.2, -0.1, 0.4) + std::sqrt(std::log(3.0 / 1.2) / 2.0) * d, d};
  }
};

// One compact blob with the cubic step kernel, a = 2 T: the sphere R = w / 2 = 0.7.
struct StepBlobKind {
  static constexpr bool kTrueDistance = false;
  static Model Build() {
    Model m;
    m.AddBlobs(BlobKernel::kUnitStep, 3, {0.0, 0.3, -0.2}, {2.0}, {1.4}, 1.0);
    return m;
  }
  static SurfacePoint Sample(std::mt19937& rng) {
    std::normal_distribution<double> g;
    const Vec d = Vec(g(rng), g(rng), g(rng)).normalized();
    return {Vec(0.0, 0.3, -0.2) + 0.7 * d, d};
  }
};

// Capsule: segment a-b, radius 0.35; half the points on the cylinder part, half on the caps.
struct CapsuleKind {
  static constexpr bool kTrueDistance = true;
  static Vec A() { return Vec(-0.4, 0.2, 0.1); }
  static Vec B() { return Vec(0.5, -0.3, 0.6); }
  static Model Build() {
    Model m;
    m.AddSkeletonOffset(SkeletonKind::kSegments, {-0.4, 0.2, 0.1, 0.5, -0.3, 0.6}, 0.35);
    return m;
  }
  static SurfacePoint Sample(std::mt19937& rng) {
    std::uniform_real_distribution<double> u(0.0, 1.0);
    std::normal_distribution<double> g;
    const Vec axis = (B() - A()).normalized();
    if (u(rng) < 0.5) {
      const Vec e1 = axis.unitOrthogonal(), e2 = axis.cross(e1);
      const double theta = 2 * M_PI * u(rng);
      const Vec radial = std::cos(theta) * e1 + std::sin(theta) * e2;
      return {A() + u(rng) * (B() - A()) + 0.35 * radial, radial};
    }
    Vec d = Vec(g(rng), g(rng), g(rng)).normalized();
    const bool at_b = d.dot(axis) > 0;
    return {(at_b ? B() : A()) + 0.35 * d, d};
  }
};

// Soft partitions, x = 0 the only cut / separator (epsilon 0.2, cubic step): the plane z = 0.3
// for x > 0 and the sphere c = (-1.5, 0, 0), r = 0.8 for x < 0 (entirely in its cell's core).
// Points at least 0.06 beyond the band |x| <= epsilon, where f is the cell's child exactly.
struct PartitionKindBase {
  static constexpr bool kTrueDistance = true;
  static SurfacePoint Sample(std::mt19937& rng) {
    std::uniform_real_distribution<double> u(0.0, 1.0);
    if (u(rng) < 0.5) return {Vec(0.26 + 1.7 * u(rng), 4 * u(rng) - 2, 0.3), Vec(0, 0, 1)};
    std::normal_distribution<double> g;
    const Vec d = Vec(g(rng), g(rng), g(rng)).normalized();
    return {Vec(-1.5, 0, 0) + 0.8 * d, d};
  }
  static void Children(Model* m, int* plane, int* sphere) {
    *plane = m->AddPrimitive(NodeType::kPlane, {0, 0, 1, 0.3});
    *sphere = m->AddPrimitive(NodeType::kSphere, {-1.5, 0, 0, 0.8});
  }
};
struct PartitionGridKind : PartitionKindBase {
  static Model Build() {
    Model m;
    int plane, sphere;
    Children(&m, &plane, &sphere);
    m.AddPartition({{0.0}, {}, {}}, 0.2, 3, {sphere, plane});  // cell 0: x < 0
    return m;
  }
};
struct PartitionSequenceKind : PartitionKindBase {
  static Model Build() {
    Model m;
    const int separator = m.AddPrimitive(NodeType::kPlane, {1, 0, 0, 0});
    int plane, sphere;
    Children(&m, &plane, &sphere);
    m.AddPartitionSequence({separator}, 0.2, 3, {plane, sphere});  // cell 0: outside, x > 0
    return m;
  }
};

template <typename Kind>
class KindProperties : public ::testing::Test {
 protected:
  Model model_ = Kind::Build();
  std::mt19937 rng_{4321};
};

using Kinds = ::testing::Types<BoxKind, ParaboloidKind, GaussianBlobKind, StepBlobKind, CapsuleKind,
                               PartitionGridKind, PartitionSequenceKind>;
TYPED_TEST_SUITE(KindProperties, Kinds);

TYPED_TEST(KindProperties, SampledSurfacePointsAreOnTheZeroSet) {
  for (int i = 0; i < 300; ++i) {
    const SurfacePoint s = TypeParam::Sample(this->rng_);
    EXPECT_NEAR(this->model_.Value(s.x), 0.0, 1e-12) << s.x.transpose();
  }
}

TYPED_TEST(KindProperties, GradientIsAlongTheOutwardNormalOnTheSurface) {
  for (int i = 0; i < 300; ++i) {
    const SurfacePoint s = TypeParam::Sample(this->rng_);
    const Vec g = this->model_.Gradient(s.x);
    EXPECT_NEAR((g.normalized() - s.n).norm(), 0.0, 1e-9) << s.x.transpose();
    if (TypeParam::kTrueDistance) {
      EXPECT_NEAR(g.norm(), 1.0, 1e-9);
    }
  }
}

TYPED_TEST(KindProperties, ValueAlongTheNormalIsTheOffsetForDistances) {
  for (int i = 0; i < 100; ++i) {
    const SurfacePoint s = TypeParam::Sample(this->rng_);
    const double slope = this->model_.Gradient(s.x).norm();
    for (double h : {-0.05, -0.01, 0.01, 0.05}) {
      const double f = this->model_.Value(s.x + h * s.n);
      if (TypeParam::kTrueDistance)
        EXPECT_NEAR(f, h, 1e-12);
      else
        EXPECT_NEAR(f, h * slope, 40 * h * h * std::max(1.0, slope));
      EXPECT_EQ(f > 0, h > 0) << "sign convention: f > 0 outside";
    }
  }
}

// f as a Ceres cost of (all parameters, point).
struct ValueCost {
  const Model* model;
  template <typename T>
  bool operator()(T const* const* blocks, T* residual) const {
    residual[0] = model->Evaluate(blocks[0], blocks[1]);
    return true;
  }
};

TYPED_TEST(KindProperties, JetDerivativesAgreeWithNumericDifferentiation) {
  ceres::DynamicAutoDiffCostFunction<ValueCost, 4> cost(new ValueCost{&this->model_});
  cost.AddParameterBlock(static_cast<int>(this->model_.parameters().size()));
  cost.AddParameterBlock(3);
  cost.SetNumResiduals(1);
  std::uniform_real_distribution<double> u(-0.3, 0.3);
  for (int i = 0; i < 50; ++i) {
    const SurfacePoint s = TypeParam::Sample(this->rng_);
    const Vec x = s.x + u(this->rng_) * s.n;
    const auto report = testsupport::CompareWithCentralDifferences(
        cost, {this->model_.parameters(), {x.x(), x.y(), x.z()}});
    EXPECT_LT(report.worst_error, 1e-7) << report.detail;
    EXPECT_GT(report.largest_entry, 0.1);
  }
}

TYPED_TEST(KindProperties, JsonRoundTripKeepsTheFunction) {
  const Model back = ModelFromJson(ModelToJson(this->model_));
  EXPECT_EQ(back.nodes().size(), this->model_.nodes().size());
  std::uniform_real_distribution<double> u(-3, 3);
  for (int i = 0; i < 200; ++i) {
    const Vec x(u(this->rng_), u(this->rng_), u(this->rng_));
    EXPECT_NEAR(back.Value(x), this->model_.Value(x),
                1e-13 * (1.0 + std::abs(this->model_.Value(x))));
  }
}

}  // namespace
}  // namespace implicitfit
