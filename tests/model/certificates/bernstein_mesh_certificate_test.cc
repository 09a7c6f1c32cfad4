// Test 4 of docs/maths.md G-1: C1 + every tetrahedron certified => convex on the whole box, checked
// by the tangent-plane sampling test across tetrahedra; and the C0 concave-kink control.
#include "model/certificates/bernstein_mesh_certificate.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <random>

#include "model/bernstein/bernstein_conversion.h"
#include "model/bernstein/bernstein_mesh_continuity.h"

namespace implicitfit {
namespace {

using Vec = Eigen::Vector3d;

std::vector<double> QuadricMesh(const BernsteinGrid& g, int k, const CartesianQuadric& q) {
  std::vector<double> b;
  for (long long t = 0; t < g.NumTetrahedra(); ++t) {
    const std::vector<double> bt = QuadricToBernstein(q, g.TetrahedronOf(t), k);
    b.insert(b.end(), bt.begin(), bt.end());
  }
  return b;
}

TEST(BernsteinMeshCertificate, RandomCertifiedC1MeshesPassSamplingOverTheWholeBox) {
  BernsteinGrid g;
  g.origin = Vec(-0.5, -0.5, -0.5);
  g.cell = 0.5;
  g.cells = {2, 2, 2};
  const int k = 3;
  const Eigen::MatrixXd N = BernsteinSplineBasis(g, k, 1);
  std::mt19937 rng(41);
  std::uniform_real_distribution<double> u(-1.0, 1.0), ev(4.0, 10.0);
  for (int trial = 0; trial < 3; ++trial) {
    // A convex quadric whose zero set (an ellipsoid) lies in the box ...
    Eigen::Matrix3d r;
    for (int i = 0; i < 9; ++i) r(i) = u(rng);
    const Eigen::Matrix3d Q = Eigen::HouseholderQR<Eigen::Matrix3d>(r).householderQ();
    const Vec lambda(ev(rng), ev(rng), ev(rng));
    CartesianQuadric q;
    q.A = Q * lambda.asDiagonal() * Q.transpose();
    const Vec c(0.1 * u(rng), 0.1 * u(rng), 0.1 * u(rng));
    q.b = -q.A * c;
    q.c = c.dot(q.A * c) - 0.1 * lambda.minCoeff();
    std::vector<double> b = QuadricMesh(g, k, q);
    // ... plus a random C1 spline perturbation, as large as the certificate allows.
    Eigen::VectorXd z(N.cols());
    for (int i = 0; i < z.size(); ++i) z[i] = u(rng);
    Eigen::VectorXd delta = N * z;
    delta /= delta.cwiseAbs().maxCoeff();
    double eps = 0.5;
    std::vector<double> trial_b;
    while (true) {
      trial_b = b;
      for (size_t i = 0; i < b.size(); ++i) trial_b[i] += eps * delta[static_cast<long>(i)];
      if (CertifyMeshConvexity(k, g, trial_b.data()).convex_on_box) break;
      eps *= 0.7;
      ASSERT_GT(eps, 1e-6);
    }
    const MeshConvexityCertificate cert = CertifyMeshConvexity(k, g, trial_b.data());
    EXPECT_EQ(cert.certified_tetrahedra, g.NumTetrahedra());
    EXPECT_LE(cert.c1_defect, 1e-12);
    // The perturbation (a generic C1 spline, not a global polynomial: test 1 shows its
    // Hessian jumps) is not negligible against the quadric's control points.
    EXPECT_GT(eps * 1.0,
              1e-3 * Eigen::Map<const Eigen::VectorXd>(b.data(), b.size()).cwiseAbs().maxCoeff());
    MeshSamplingOptions options;
    options.segments = 10000;
    options.seed = 100 + trial;
    const MeshSamplingResult s = MeshTangentPlaneTest(k, g, trial_b.data(), options);
    EXPECT_GT(s.zero_points, 1000);
    EXPECT_EQ(s.violations, 0) << "worst excursion " << s.worst_excursion;
  }
}

TEST(BernsteinMeshCertificate, C0MeshWithAConcaveKinkIsNotConvex) {
  // f = |x|^2 - 0.16 - 0.3 |x0| on [-1, 1] x [-0.5, 0.5]^2: two cubes, one convex quadric each
  // (Hessian 2 I, certified), joined C0 on x0 = 0 with a concave kink.
  BernsteinGrid g;
  g.origin = Vec(-1.0, -0.5, -0.5);
  g.cell = 1.0;
  g.cells = {2, 1, 1};
  const int k = 2;
  CartesianQuadric left, right;
  left.A = right.A = Eigen::Matrix3d::Identity();
  left.c = right.c = -0.16;
  left.b = Vec(0.15, 0, 0);    // + 0.3 x0 for x0 < 0
  right.b = Vec(-0.15, 0, 0);  // - 0.3 x0 for x0 > 0
  std::vector<double> b;
  for (long long t = 0; t < g.NumTetrahedra(); ++t) {
    const std::vector<double> bt = QuadricToBernstein(t < 6 ? left : right, g.TetrahedronOf(t), k);
    b.insert(b.end(), bt.begin(), bt.end());
  }
  EXPECT_LE(ContinuityDefect(g, k, 0, b.data()), 1e-14);  // C0 holds
  const MeshConvexityCertificate cert = CertifyMeshConvexity(k, g, b.data());
  EXPECT_EQ(cert.certified_tetrahedra, 12);
  EXPECT_GT(cert.c1_defect, 1e-2);
  EXPECT_FALSE(cert.c1);
  EXPECT_FALSE(cert.convex_on_box);
  const MeshSamplingResult s = MeshTangentPlaneTest(k, g, b.data());
  EXPECT_GT(s.violations, 0);
}

}  // namespace
}  // namespace implicitfit
