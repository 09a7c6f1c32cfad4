// Random Bernstein patches for tests, a mix of convex and non-convex ones. Control points
//   b_lambda = lambda^T S lambda / k^2 + (affine in lambda) + noise,
// with S = R R^T + a I (4x4, positive definite). For the quadratic part every A^mu equals
// 2 P^T S P / k^2, P = [e1 - e4, e2 - e4, e3 - e4] (a second difference of a quadratic form),
// so it is positive definite; the affine part does not change A^mu; the noise (amplitude drawn
// per patch from 0 to 0.5) makes some of them indefinite.
#pragma once

#include <Eigen/Dense>
#include <array>
#include <random>
#include <vector>

namespace testsupport {

// Four random vertices in [-2, 2]^3 whose edge matrix has |det| > min_det (not flat).
inline std::array<Eigen::Vector3d, 4> RandomCorners(std::mt19937& rng, double min_det = 0.5) {
  std::uniform_real_distribution<double> u(-2.0, 2.0);
  while (true) {
    std::array<Eigen::Vector3d, 4> c;
    for (Eigen::Vector3d& v : c) v = Eigen::Vector3d(u(rng), u(rng), u(rng));
    Eigen::Matrix3d e;
    for (int i = 0; i < 3; ++i) e.col(i) = c[i] - c[3];
    if (std::abs(e.determinant()) > min_det) return c;
  }
}

// A random symmetric matrix with the given eigenvalues (random orthogonal frame).
inline Eigen::Matrix3d RandomSymmetric(std::mt19937& rng, const Eigen::Vector3d& eigenvalues) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Eigen::Matrix3d r;
  for (int i = 0; i < 9; ++i) r(i) = u(rng);
  const Eigen::Matrix3d q = Eigen::HouseholderQR<Eigen::Matrix3d>(r).householderQ();
  return q * eigenvalues.asDiagonal() * q.transpose();
}

inline std::vector<double> RandomMixedPatch(std::mt19937& rng, int k) {
  std::uniform_real_distribution<double> u(-1.0, 1.0), amplitude(0.0, 0.5);
  Eigen::Matrix4d r;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) r(i, j) = u(rng);
  const Eigen::Matrix4d s = r * r.transpose() + 0.05 * Eigen::Matrix4d::Identity();
  const Eigen::Vector4d affine(u(rng), u(rng), u(rng), u(rng));
  const double offset = u(rng), noise = amplitude(rng);
  std::vector<double> b;
  for (int a = k; a >= 0; --a)
    for (int c = k - a; c >= 0; --c)
      for (int d = k - a - c; d >= 0; --d) {
        const Eigen::Vector4d l(a, c, d, k - a - c - d);
        b.push_back(l.dot(s * l) / (k * k) + affine.dot(l) / k + offset + noise * u(rng));
      }
  return b;
}

}  // namespace testsupport
