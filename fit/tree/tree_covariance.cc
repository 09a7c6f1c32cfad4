#include "fit/tree/tree_covariance.h"

#include <Eigen/Dense>
#include <cmath>

namespace implicitfit {

std::vector<double> TreeStandardDeviations(const Model& model,
                                           const std::vector<Eigen::Vector3d>& points) {
  const int P = static_cast<int>(model.parameters().size());
  const int N = static_cast<int>(points.size());
  std::vector<double> sd(P, 0.0);
  if (N <= P || P == 0) return sd;
  std::vector<double> theta = model.parameters();
  Eigen::MatrixXd JtJ = Eigen::MatrixXd::Zero(P, P);
  Eigen::VectorXd row(P);
  double rss = 0.0;
  for (const Eigen::Vector3d& x : points) {
    double f;
    const double g = model.Gradient(x, &f).norm();
    if (!(g > 0) || !std::isfinite(g)) continue;
    rss += (f / g) * (f / g);
    for (int j = 0; j < P; ++j) {
      const double t0 = theta[j], h = 1e-6 * (1.0 + std::abs(t0));
      theta[j] = t0 + h;
      const double fp = model.Evaluate<double>(theta.data(), x.data());
      theta[j] = t0 - h;
      const double fm = model.Evaluate<double>(theta.data(), x.data());
      theta[j] = t0;
      row[j] = (fp - fm) / (2 * h * g);
    }
    JtJ.selfadjointView<Eigen::Lower>().rankUpdate(row);
  }
  JtJ = JtJ.selfadjointView<Eigen::Lower>();
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(JtJ);
  const Eigen::VectorXd& lambda = eig.eigenvalues();
  const double cut = 1e-10 * lambda.cwiseAbs().maxCoeff();
  Eigen::VectorXd inv = Eigen::VectorXd::Zero(P);
  int rank = 0;
  for (int i = 0; i < P; ++i)
    if (lambda[i] > cut) {
      inv[i] = 1.0 / lambda[i];
      ++rank;
    }
  const double sigma2 = rss / std::max(1, N - rank);
  const Eigen::MatrixXd cov =
      eig.eigenvectors() * inv.asDiagonal() * eig.eigenvectors().transpose();
  for (int j = 0; j < P; ++j) sd[j] = std::sqrt(std::max(0.0, sigma2 * cov(j, j)));
  return sd;
}

}  // namespace implicitfit
