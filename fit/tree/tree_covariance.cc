#include "fit/tree/tree_covariance.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <numeric>

namespace implicitfit {

std::vector<double> TreeStandardDeviations(const Model& model,
                                           const std::vector<Eigen::Vector3d>& points,
                                           const std::vector<int>& columns) {
  const int P = static_cast<int>(columns.size());
  const int N = static_cast<int>(points.size());
  std::vector<double> sd(model.parameters().size(), 0.0);
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
    for (int c = 0; c < P; ++c) {
      const int j = columns[c];
      const double t0 = theta[j], h = 1e-6 * (1.0 + std::abs(t0));
      theta[j] = t0 + h;
      const double fp = model.Evaluate<double>(theta.data(), x.data());
      theta[j] = t0 - h;
      const double fm = model.Evaluate<double>(theta.data(), x.data());
      theta[j] = t0;
      row[c] = (fp - fm) / (2 * h * g);
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
  for (int c = 0; c < P; ++c) sd[columns[c]] = std::sqrt(std::max(0.0, sigma2 * cov(c, c)));
  return sd;
}

std::vector<double> TreeStandardDeviations(const Model& model,
                                           const std::vector<Eigen::Vector3d>& points) {
  std::vector<int> all(model.parameters().size());
  std::iota(all.begin(), all.end(), 0);
  return TreeStandardDeviations(model, points, all);
}

std::vector<int> FreeParameterColumns(const Model& model) {
  std::vector<int> columns;
  for (const ModelNode& node : model.nodes()) {
    const std::vector<ParameterField>& fields = ParameterFieldsOf(node.type);
    int size = 0;
    for (const ParameterField& field : fields) size += field.size;
    const bool per_field = !fields.empty() && size == node.num_parameters;
    if (!per_field) {  // per-element or per-node layouts: free unless the node lists a field
      if (node.fixed.empty())
        for (int i = 0; i < node.num_parameters; ++i) columns.push_back(node.first_parameter + i);
      continue;
    }
    int offset = node.first_parameter;
    for (const ParameterField& field : fields) {
      const bool fixed =
          std::find(node.fixed.begin(), node.fixed.end(), field.name) != node.fixed.end();
      if (!fixed)
        for (int i = 0; i < field.size; ++i) columns.push_back(offset + i);
      offset += field.size;
    }
  }
  std::sort(columns.begin(), columns.end());
  return columns;
}

}  // namespace implicitfit
