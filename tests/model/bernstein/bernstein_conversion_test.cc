// Quadric <-> Bernstein conversion and degree elevation (model/bernstein/bernstein_conversion.h),
// checked against direct evaluation of the quadric and the naive oracle.
#include "model/bernstein/bernstein_conversion.h"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <random>

#include "model/certificates/convexity_certificate.h"
#include "oracle/bernstein_oracle.h"
#include "support/random_patches.h"

namespace implicitfit {
namespace {

using Vec = Eigen::Vector3d;
using Corners = std::array<Vec, 4>;

using testsupport::RandomCorners;

CartesianQuadric RandomQuadric(std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  CartesianQuadric q;
  for (int i = 0; i < 3; ++i)
    for (int j = i; j < 3; ++j) q.A(i, j) = q.A(j, i) = u(rng);
  q.b = Vec(u(rng), u(rng), u(rng));
  q.c = u(rng);
  return q;
}

TEST(BernsteinConversion, QuadricPatchEvaluatesToTheQuadricAtEveryDegree) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-3.0, 3.0);
  for (int k = 2; k <= 5; ++k)
    for (int trial = 0; trial < 10; ++trial) {
      const Corners c = RandomCorners(rng);
      const CartesianQuadric q = RandomQuadric(rng);
      const std::vector<double> b = QuadricToBernstein(q, Tetrahedron(c[0], c[1], c[2], c[3]), k);
      ASSERT_EQ(static_cast<long long>(b.size()), NumBernsteinControlPoints(k));
      for (int i = 0; i < 20; ++i) {
        const Vec x(u(rng), u(rng), u(rng));
        double magnitude;
        const double f = oracle::Patch(k, b, c, x, &magnitude);
        EXPECT_NEAR(f, q(x), 1e-12 * (1.0 + magnitude));
      }
    }
}

TEST(BernsteinConversion, RoundTripsBothWays) {
  std::mt19937 rng(12);
  std::uniform_real_distribution<double> u(-3.0, 3.0);
  for (int trial = 0; trial < 50; ++trial) {
    const Corners c = RandomCorners(rng);
    const Tetrahedron tet(c[0], c[1], c[2], c[3]);
    const CartesianQuadric q = RandomQuadric(rng);
    const std::vector<double> b = QuadricToBernstein(q, tet);
    const CartesianQuadric back = BernsteinToQuadric(b.data(), tet);
    EXPECT_LT((back.A - q.A).norm(), 1e-10);
    EXPECT_LT((back.b - q.b).norm(), 1e-10);
    EXPECT_NEAR(back.c, q.c, 1e-10);
    // Random control points -> quadric -> evaluates like the oracle -> same control points.
    std::vector<double> r(10);
    for (double& x : r) x = u(rng);
    const CartesianQuadric qr = BernsteinToQuadric(r.data(), tet);
    for (int i = 0; i < 10; ++i) {
      const Vec x(u(rng), u(rng), u(rng));
      EXPECT_NEAR(qr(x), oracle::Patch(2, r, c, x), 1e-9 * (1.0 + std::abs(qr(x))));
    }
    const std::vector<double> again = QuadricToBernstein(qr, tet);
    for (int i = 0; i < 10; ++i) EXPECT_NEAR(again[i], r[i], 1e-10);
  }
}

TEST(BernsteinConversion, DegreeElevationNeverChangesF) {
  std::mt19937 rng(13);
  std::uniform_real_distribution<double> u(-3.0, 3.0);
  for (int k = 1; k <= 5; ++k)
    for (int trial = 0; trial < 10; ++trial) {
      const Corners c = RandomCorners(rng);
      std::vector<double> b(static_cast<size_t>(NumBernsteinControlPoints(k)));
      for (double& x : b) x = u(rng);
      const std::vector<double> e = ElevateDegree(k, b);
      ASSERT_EQ(static_cast<long long>(e.size()), NumBernsteinControlPoints(k + 1));
      for (int i = 0; i < 20; ++i) {
        const Vec x(u(rng), u(rng), u(rng));
        const double f = oracle::Patch(k, b, c, x);
        EXPECT_NEAR(oracle::Patch(k + 1, e, c, x), f, 1e-10 * (1.0 + std::abs(f)));
      }
    }
  EXPECT_THROW(ElevateDegree(2, std::vector<double>(9)), std::invalid_argument);
}

// The A^mu of the elevated patch (degree k+1) are (k-1)/(k+1) times convex combinations of the
// old ones: the second-derivative polynomial sum A^mu B^{k-2}_mu elevates like any polynomial, and
// A carries no k(k-1) factor. So a certified patch stays certified, with
// min_eigenvalue' >= (k-1)/(k+1) min_eigenvalue.
TEST(BernsteinConversion, ElevationKeepsACertifiedPatchCertified) {
  std::mt19937 rng(14);
  int certified = 0;
  for (int k = 2; k <= 4; ++k)
    for (int trial = 0; trial < 300; ++trial) {
      const std::vector<double> b = testsupport::RandomMixedPatch(rng, k);
      const oracle::Certificate before = oracle::Certify(k, b);
      if (!before.convex) continue;
      ++certified;
      std::vector<double> e = b;
      double bound = before.min_eigenvalue;
      for (int d = k; d < k + 3; ++d) {
        e = ElevateDegree(d, e);
        bound *= double(d - 1) / (d + 1);
        const ConvexityCertificate after = CertifyConvexity(d + 1, e.data());
        EXPECT_TRUE(after.convex);
        EXPECT_GE(after.min_eigenvalue, bound - 1e-12 * before.scale);
      }
    }
  EXPECT_GT(certified, 100);
}

}  // namespace
}  // namespace implicitfit
