// Numerical Cramer-Rao bound for recovery tests: for residuals r_i(theta) = r(theta, x_i) with
// independent N(0, sigma^2) noise, the covariance of any unbiased estimator is at least
//   C = sigma^2 (J^T J)^(-1),   J_ik = d r(theta, x_i) / d theta_k   at the truth,
// J by central differences (step 1e-6) over a local parameterisation theta = theta_0 + delta
// supplied by the caller (e.g. a rotation vector for a quaternion), so the result does not
// depend on the code under test beyond the model's value.
#pragma once

#include <Eigen/Dense>
#include <functional>
#include <vector>

namespace testsupport {

// residual(delta, x): the residual at x for parameters theta_0 + delta (delta of size dim).
inline Eigen::MatrixXd CramerRaoCovariance(
    const std::function<double(const Eigen::VectorXd&, const Eigen::Vector3d&)>& residual, int dim,
    const std::vector<Eigen::Vector3d>& points, double sigma) {
  Eigen::MatrixXd jtj = Eigen::MatrixXd::Zero(dim, dim);
  const double h = 1e-6;
  Eigen::VectorXd row(dim);
  for (const Eigen::Vector3d& x : points) {
    for (int k = 0; k < dim; ++k) {
      Eigen::VectorXd d = Eigen::VectorXd::Zero(dim);
      d[k] = h;
      const double plus = residual(d, x);
      d[k] = -h;
      row[k] = (plus - residual(d, x)) / (2 * h);
    }
    jtj += row * row.transpose();
  }
  return sigma * sigma * jtj.inverse();
}

// Root of the trace of the block [begin, begin + size): the spread of that group's error norm.
inline double Spread(const Eigen::MatrixXd& covariance, int begin, int size) {
  return std::sqrt(covariance.block(begin, begin, size, size).trace());
}

}  // namespace testsupport
