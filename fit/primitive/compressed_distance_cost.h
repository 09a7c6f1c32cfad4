// One Ceres residual block that stands for a chunk of n point residuals r_i = f(x_i; theta)
// (the primitive's signed distance) with only P + 1 residuals, P = number of parameters.
//
// Maths. Ceres' trust-region step (Levenberg-Marquardt with the dense normal equations), its
// step quality, the gradient and the covariance use the residuals and Jacobian only through
//   A = J^T J (P x P),   b = J^T r (P),   c = r^T r,
// J the n x P Jacobian df(x_i)/dtheta. Any r' (P + 1) and J' ((P + 1) x P) with
// J'^T J' = A, J'^T r' = b and r'^T r' = c give the same steps, costs and covariance. Here,
// with D = diag(sqrt(A_jj)) and the eigen-decomposition D^-1 A D^-1 = V L V^T (scaled for
// accuracy; L >= 0):
//   J' = [ L^(1/2) V^T D ; 0 ],
//   r'_k = (V^T D^-1 b)_k / sqrt(L_k)  for L_k > 1e-14 max L, else 0   (k < P),
//   r'_P = sqrt(max(0, c - sum_k r'_k^2)).
// Then J'^T J' = A, and J'^T r' = b because D^-1 b = (J D^-1)^T r lies in the range of
// D^-1 A D^-1 (the zero eigenvalues of a gauge freedom, e.g. the cylinder's point sliding
// along the axis, drop out of both). Residual-only evaluations return r' = (sqrt(c), 0, ...).
// A block held constant gets no Jacobian; the free columns of J' still reproduce the free part
// of A and b. Manifolds (the axis on the unit sphere) multiply J' by their plus-Jacobian, which
// keeps the identities.
//
// Why: per point, Ceres' own machinery (scratch Jacobians, validity checks, the copy into the
// dense Jacobian, column scaling, J^T J) cost as much as the closed-form derivatives
// themselves (fit/primitive/primitive_jacobians.h); here a point costs its derivatives and a rank-one
// update of A. Several chunks (blocks) keep Ceres' multithreaded evaluation.
#pragma once

#include <ceres/ceres.h>

#include <Eigen/Core>
#include <Eigen/Eigenvalues>
#include <cmath>
#include <vector>

#include "fit/primitive/point_chunk_cost.h"
#include "fit/primitive/primitive_jacobians.h"

namespace implicitfit {

template <typename Evaluator>
class CompressedDistanceCost final : public PointChunkCost {
 public:
  static constexpr int kP = Evaluator::kNumParameters;
  static_assert(PrimitiveDistance<Evaluator>::kAvailable, "needs closed-form derivatives");

  // kP + 1 residuals for the points of `indices` (see fit/primitive/point_chunk_cost.h).
  CompressedDistanceCost(const double* xyz, std::vector<int> indices,
                         const std::vector<int>& block_sizes)
      : PointChunkCost(xyz, std::move(indices), block_sizes, kP + 1) {}

  bool Evaluate(double const* const* parameters, double* residuals,
                double** jacobians) const override {
    using Matrix = Eigen::Matrix<double, kP, kP>;
    using Vector = Eigen::Matrix<double, kP, 1>;
    const std::vector<int32_t>& sizes = parameter_block_sizes();
    double p[kP];
    Gather(parameters, p);
    const PrimitiveDistance<Evaluator> f(p);
    double c = 0.0;
    if (!jacobians) {
      for (int i : indices_) {
        const double r = f(xyz_ + 3 * i, nullptr, nullptr);
        c += r * r;
      }
      residuals[0] = std::sqrt(c);
      for (int k = 1; k <= kP; ++k) residuals[k] = 0.0;
      return std::isfinite(c);
    }
    Matrix a = Matrix::Zero();
    Vector g = Vector::Zero();
    Vector dp;
    for (int i : indices_) {
      const double r = f(xyz_ + 3 * i, dp.data(), nullptr);
      c += r * r;
      g += r * dp;
      for (int j = 0; j < kP;
           ++j)  // lower triangle; Eigen's rankUpdate is an out-of-line call per point
        for (int k = 0; k <= j; ++k) a(j, k) += dp[j] * dp[k];
    }
    a = a.template selfadjointView<Eigen::Lower>();
    if (!std::isfinite(c) || !a.allFinite()) return false;
    Vector d;
    for (int j = 0; j < kP; ++j) d[j] = a(j, j) > 0 ? std::sqrt(a(j, j)) : 1.0;
    const Matrix scaled = d.cwiseInverse().asDiagonal() * a * d.cwiseInverse().asDiagonal();
    const Eigen::SelfAdjointEigenSolver<Matrix> eig(scaled);
    const Vector lambda = eig.eigenvalues().cwiseMax(0.0);
    const Vector projected = eig.eigenvectors().transpose() * d.cwiseInverse().asDiagonal() * g;
    const double floor = 1e-14 * lambda.maxCoeff();
    double explained = 0.0;
    for (int k = 0; k < kP; ++k) {
      residuals[k] = lambda[k] > floor ? projected[k] / std::sqrt(lambda[k]) : 0.0;
      explained += residuals[k] * residuals[k];
    }
    residuals[kP] = std::sqrt(std::max(0.0, c - explained));
    // J' rows k < kP: sqrt(lambda_k) (V^T D)_k; row kP: 0.
    const Matrix jp =
        lambda.cwiseSqrt().asDiagonal() * eig.eigenvectors().transpose() * d.asDiagonal();
    for (size_t b = 0; b < sizes.size(); ++b) {
      if (!jacobians[b]) continue;
      for (int k = 0; k <= kP; ++k)
        for (int j = 0; j < sizes[b]; ++j)
          jacobians[b][k * sizes[b] + j] = k < kP ? jp(k, offsets_[b] + j) : 0.0;
    }
    return true;
  }
};

}  // namespace implicitfit
