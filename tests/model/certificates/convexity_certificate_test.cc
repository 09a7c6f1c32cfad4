// The convexity certificate (model/certificates/convexity_certificate.h) against (a) quadrics of known
// definiteness, through the relation derived in the header: Hess f = k(k-1) E^-T A E^-1, so a
// quadric x^T Q x + ... (Hessian 2Q) has A^mu = 2/(k(k-1)) E^T Q E for every mu;
// (b) A^mu built longhand by the oracle and Eigen's iterative eigen solver.
#include "model/certificates/convexity_certificate.h"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <random>

#include "model/bernstein/bernstein_conversion.h"
#include "oracle/bernstein_oracle.h"
#include "support/random_patches.h"

namespace implicitfit {
namespace {

using Vec = Eigen::Vector3d;

Tetrahedron RandomTetrahedron(std::mt19937& rng, Eigen::Matrix3d* edges) {
  const auto c = testsupport::RandomCorners(rng, 0.3);
  for (int i = 0; i < 3; ++i) edges->col(i) = c[i] - c[3];
  return Tetrahedron(c[0], c[1], c[2], c[3]);
}

TEST(ConvexityCertificate, QuadricsGetTheVerdictOfTheirMatrixOnEveryTetrahedron) {
  std::mt19937 rng(21);
  std::uniform_real_distribution<double> u(-1.0, 1.0), pos(0.1, 2.0);
  const Vec spectra[] = {Vec(1, 2, 3),    Vec(0.1, 0.5, 4), Vec(-1, 2, 3), Vec(1, -0.2, 3),
                         Vec(-1, -2, -3), Vec(0, 1, 2),     Vec(2, 2, 2)};
  const bool convex[] = {true, true, false, false, false, false, true};
  for (int s = 0; s < 7; ++s)
    for (int trial = 0; trial < 10; ++trial) {
      Eigen::Matrix3d e;
      const Tetrahedron tet = RandomTetrahedron(rng, &e);
      CartesianQuadric q;
      q.A = testsupport::RandomSymmetric(rng, spectra[s]);
      q.b = Vec(u(rng), u(rng), u(rng));
      q.c = u(rng);
      const double base =
          Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(e.transpose() * q.A * e).eigenvalues()(0);
      for (int k = 2; k <= 4; ++k) {
        const std::vector<double> b = QuadricToBernstein(q, tet, k);
        const ConvexityCertificate cert = CertifyConvexity(k, b.data());
        EXPECT_EQ(cert.convex, convex[s]) << "spectrum " << spectra[s].transpose() << " k " << k;
        EXPECT_EQ(cert.num_matrices, (k - 1) * k * (k + 1) / 6);
        const double expected = 2.0 / (k * (k - 1)) * base;
        EXPECT_NEAR(cert.min_eigenvalue, expected, 1e-9 * std::max(1.0, std::abs(expected)));
      }
    }
}

TEST(ConvexityCertificate, MatchesLonghandMatricesOnThousandsOfRandomPatches) {
  std::mt19937 rng(22);
  int convex = 0, total = 0;
  for (int k = 2; k <= 5; ++k)
    for (int trial = 0; trial < 1500; ++trial) {
      const std::vector<double> b = testsupport::RandomMixedPatch(rng, k);
      const oracle::Certificate expected = oracle::Certify(k, b);
      const ConvexityCertificate got = CertifyConvexity(k, b.data());
      EXPECT_EQ(got.convex, expected.convex);
      EXPECT_NEAR(got.min_eigenvalue, expected.min_eigenvalue,
                  1e-9 * std::abs(expected.min_eigenvalue) + 1e-14 * expected.scale);
      convex += expected.convex;
      ++total;
    }
  // Both verdicts well represented.
  EXPECT_GT(convex, total / 10);
  EXPECT_LT(convex, total - total / 10);
}

TEST(ConvexityCertificate, CubicNeedsAllFourVertexMatrices) {
  // A cubic whose sub-quadric at vertex m is convex except at one vertex (Guo §4: four matrices).
  std::mt19937 rng(23);
  for (int bad = 0; bad < 4; ++bad) {
    // b_lambda = sum_m lambda_m/3 * c^m_{lambda - e_m}-like construction: start from a convex
    // cubic (elevated sphere quadric) and lower one control point on the A^{e_bad} stencil.
    CartesianQuadric sphere;
    sphere.A = Eigen::Matrix3d::Identity();
    sphere.c = -1.0;
    std::vector<double> b = QuadricToBernstein(sphere, Tetrahedron(), 3);
    const auto order = oracle::DesignOrder(3);
    // Push the b(mu + 2 e_1) entry of mu = e_bad far down: A^{e_bad}_11 becomes negative.
    oracle::MultiIndex target = {2, 0, 0, 0};
    ++target[bad];
    for (size_t i = 0; i < order.size(); ++i)
      if (order[i] == target) b[i] -= 10.0;
    const ConvexityCertificate cert = CertifyConvexity(3, b.data());
    EXPECT_FALSE(cert.convex) << bad;
    EXPECT_EQ(cert.num_matrices, 4);
    EXPECT_NEAR(cert.min_eigenvalue, oracle::Certify(3, b).min_eigenvalue, 1e-12);
  }
}

TEST(ConvexityCertificate, ExtremeMagnitudesNeitherOverflowNorUnderflow) {
  std::mt19937 rng(24);
  for (int trial = 0; trial < 50; ++trial) {
    const std::vector<double> b = testsupport::RandomMixedPatch(rng, 3);
    const ConvexityCertificate base = CertifyConvexity(3, b.data());
    for (double scale : {0x1p1000, 0x1p-1000}) {  // exact powers of two, normal results
      std::vector<double> s = b;
      for (double& x : s) x *= scale;
      const ConvexityCertificate c = CertifyConvexity(3, s.data());
      EXPECT_EQ(c.convex, base.convex) << scale;
      EXPECT_NEAR(c.min_eigenvalue / scale, base.min_eigenvalue,
                  1e-12 * std::abs(base.min_eigenvalue) + 1e-14)
          << scale;
    }
  }
}

TEST(ConvexityCertificate, DegreeOneIsConvexWithZeroMargin) {
  const double plane[4] = {1, -2, 0.5, 3};
  const ConvexityCertificate cert = CertifyConvexity(1, plane);
  EXPECT_TRUE(cert.convex);
  EXPECT_EQ(cert.min_eigenvalue, 0.0);
  EXPECT_EQ(cert.num_matrices, 0);
}

TEST(ConvexityCertificate, AffineContentIsNotStrictlyConvex) {
  // A plane elevated to degree 2: every A^mu = 0, so not certified (conservative by design).
  std::vector<double> b = {0.3, 0.1, -0.2, 0.7};
  b = ElevateDegree(1, b);
  const ConvexityCertificate cert = CertifyConvexity(2, b.data());
  EXPECT_FALSE(cert.convex);
  EXPECT_NEAR(cert.min_eigenvalue, 0.0, 1e-15);
}

}  // namespace
}  // namespace implicitfit
