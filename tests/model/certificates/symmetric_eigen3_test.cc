// Closed-form 3x3 symmetric eigenvalues (model/certificates/symmetric_eigen3.h) against Eigen's iterative
// solver, including near-double and triple eigenvalues where the plain trigonometric formula
// loses half the digits.
#include "model/certificates/symmetric_eigen3.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <random>

#include "support/random_patches.h"

namespace implicitfit {
namespace {

void ExpectMatchesEigen(const Eigen::Matrix3d& a, double relative) {
  const double packed[6] = {a(0, 0), a(1, 1), a(2, 2), a(0, 1), a(0, 2), a(1, 2)};
  double got[3];
  SymmetricEigenvalues3(packed, got);
  const Eigen::Vector3d expected = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(a).eigenvalues();
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(got[i], expected[i], relative * a.norm()) << a;
  EXPECT_NEAR(SymmetricMinEigenvalue3(packed), expected[0], relative * a.norm()) << a;
}

using testsupport::RandomSymmetric;

TEST(SymmetricEigen3, RandomMatrices) {
  std::mt19937 rng(31);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int i = 0; i < 20000; ++i) {
    Eigen::Matrix3d a;
    for (int r = 0; r < 3; ++r)
      for (int c = r; c < 3; ++c) a(r, c) = a(c, r) = u(rng);
    ExpectMatchesEigen(a, 1e-14);
  }
}

TEST(SymmetricEigen3, NearlyRepeatedEigenvaluesAndExtremeScales) {
  std::mt19937 rng(32);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int i = 0; i < 5000; ++i) {
    const double l = u(rng), gap = std::pow(10.0, -16.0 * std::abs(u(rng)));
    ExpectMatchesEigen(RandomSymmetric(rng, Eigen::Vector3d(l, l + gap, 2.0 * u(rng))), 1e-14);
    ExpectMatchesEigen(RandomSymmetric(rng, Eigen::Vector3d(l, l + gap, l - gap)), 1e-14);
    ExpectMatchesEigen(RandomSymmetric(rng, Eigen::Vector3d(0.0, gap, 1.0)), 1e-14);
  }
  for (double scale : {1e-150, 1e-8, 1e8, 1e150})
    ExpectMatchesEigen(scale * RandomSymmetric(rng, Eigen::Vector3d(1, -2, 3)), 1e-14);
  ExpectMatchesEigen(Eigen::Matrix3d::Zero(), 0.0);
  ExpectMatchesEigen(Eigen::Vector3d(3, 1, 2).asDiagonal().toDenseMatrix(), 1e-15);
  ExpectMatchesEigen(4.0 * Eigen::Matrix3d::Identity(), 1e-15);
}

}  // namespace
}  // namespace implicitfit
