// The sampling second opinion (model/certificates/tangent_plane_test.h): it must never find a violation on a
// certified patch, and must find one on patches whose zero set is visibly not convex.
#include "model/certificates/tangent_plane_test.h"

#include <gtest/gtest.h>

#include <random>

#include "model/bernstein/bernstein_conversion.h"
#include "model/certificates/convexity_certificate.h"
#include "support/random_patches.h"

namespace implicitfit {
namespace {

using Vec = Eigen::Vector3d;

const Tetrahedron kAroundOrigin(Vec(1.5, 1.5, 1.5), Vec(1.5, -1.5, -1.5), Vec(-1.5, 1.5, -1.5),
                                Vec(-1.5, -1.5, 1.5));

TEST(TangentPlaneTest, NeverContradictsTheCertificate) {
  std::mt19937 rng(41);
  int certified = 0, with_points = 0;
  TangentPlaneTestOptions options;
  options.segments = 200;
  for (int k = 2; k <= 4; ++k)
    for (int trial = 0; trial < 150; ++trial) {
      const std::vector<double> b = testsupport::RandomMixedPatch(rng, k);
      if (!CertifyConvexity(k, b.data()).convex) continue;
      ++certified;
      options.seed = static_cast<std::uint64_t>(trial);
      const TangentPlaneTestResult r = TangentPlaneTest(k, kAroundOrigin, b.data(), options);
      with_points += r.zero_points >= 2;
      EXPECT_EQ(r.violations, 0) << "k " << k << " trial " << trial;
    }
  EXPECT_GT(certified, 50);
  EXPECT_GT(with_points, 10);  // the test had something to look at
}

TEST(TangentPlaneTest, SphereIsConvexHyperboloidIsNot) {
  CartesianQuadric sphere;
  sphere.A = Eigen::Matrix3d::Identity();
  sphere.c = -1.0;
  const std::vector<double> s = QuadricToBernstein(sphere, kAroundOrigin);
  const TangentPlaneTestResult rs = TangentPlaneTest(2, kAroundOrigin, s.data());
  EXPECT_GT(rs.zero_points, 100);
  EXPECT_EQ(rs.violations, 0);

  CartesianQuadric hyperboloid;  // x^2 + y^2 - z^2 - 0.25: one sheet, saddle-shaped everywhere
  hyperboloid.A = Eigen::Vector3d(1, 1, -1).asDiagonal();
  hyperboloid.c = -0.25;
  const std::vector<double> h = QuadricToBernstein(hyperboloid, kAroundOrigin);
  EXPECT_FALSE(CertifyConvexity(2, h.data()).convex);
  const TangentPlaneTestResult rh = TangentPlaneTest(2, kAroundOrigin, h.data());
  EXPECT_GT(rh.zero_points, 100);
  EXPECT_GT(rh.violations, rh.zero_points / 2);
}

TEST(TangentPlaneTest, NoZeroSetNoPoints) {
  const std::vector<double> positive(20, 1.0);
  const TangentPlaneTestResult r = TangentPlaneTest(3, kAroundOrigin, positive.data());
  EXPECT_EQ(r.zero_points, 0);
  EXPECT_EQ(r.violations, 0);
}

}  // namespace
}  // namespace implicitfit
