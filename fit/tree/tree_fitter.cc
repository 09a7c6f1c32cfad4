#include "fit/tree/tree_fitter.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <thread>

#include "fit/common/thread_count.h"
#include "fit/tree/tree_parameters.h"
#include "fit/tree/tree_point_residual.h"
#include "model/median.h"

namespace implicitfit {

bool TreeFitOptions::IsValid(std::string* error) const {
  auto fail = [error](const std::string& e) {
    if (error) *error = e;
    return false;
  };
  if (!(normal_weight >= 0.0) || !std::isfinite(normal_weight))
    return fail("normal_weight must be a finite number >= 0");
  if (max_iterations < 1) return fail("max_iterations must be >= 1");
  if (num_threads < 0) return fail("num_threads must be >= 0 (0: one per core)");
  return true;
}

TreeFitResult FitModelTree(const Model& initial, const std::vector<Eigen::Vector3d>& points,
                           const std::vector<Eigen::Vector3d>& normals,
                           const TreeFitOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  TreeFitResult result;
  result.model = initial;
  result.model.mutable_claims() = ModelClaims{};  // the claims were of the initial parameters
  const size_t n_points = points.size();
  result.points = n_points;
  std::string error;
  if (!options.IsValid(&error)) {
    result.message = error;
    return result;
  }
  if (n_points < 5) {
    result.message = "too few points: " + std::to_string(n_points);
    return result;
  }
  Eigen::Vector3d lo = points[0], hi = points[0];
  for (const auto& p : points) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  const double diagonal = (hi - lo).norm();
  const double h = 1e-6 * std::max(1.0, diagonal);
  const bool has_normals = normals.size() == n_points;

  TreeParameters parameters(initial);
  if (parameters.blocks().empty()) {
    result.message = "every parameter of the model is fixed: nothing to fit";
    return result;
  }
  std::vector<double*> block_ptrs;
  for (auto& b : parameters.blocks()) block_ptrs.push_back(b.data());
  {
    // Dense QR on (points x residuals) rows and P columns costs rows P^2 per iteration, with
    // every residual's autodiff over all P: a 4x4x4 partition of planes (P = 256) on 2000
    // points ran over 90 s. Refused above kMaxTreeFitWork (about a minute) instead.
    double free = 0;
    for (int size : parameters.block_sizes()) free += size;
    const double rows = static_cast<double>(n_points) * (has_normals ? 4 : 1);
    if (options.max_work > 0 && rows * free * free > options.max_work) {
      char text[300];
      std::snprintf(text, sizeof text,
                    "%.0f free parameters on %zu points: the dense fit would cost %.3g "
                    "(rows x parameters^2), more than the limit of %.3g (about a minute); fit "
                    "fewer parameters (a smaller grid, fixed fields) or fewer points",
                    free, n_points, rows * free * free, options.max_work);
      result.message = text;
      return result;
    }
  }

  auto residual_distances = [&](const std::vector<double>& flat) {
    Model m = initial;
    m.mutable_parameters() = flat;
    std::vector<double> d(n_points);
    for (size_t i = 0; i < n_points; ++i) {
      double f;
      const Eigen::Vector3d g = m.Gradient(points[i], &f);
      d[i] = f / std::sqrt(g.squaredNorm() + 1e-12);
    }
    return d;
  };

  const std::vector<char> constant = parameters.ConstantSubtrees(result.model);
  double loss_scale = 0.01 * diagonal;
  const int threads = ThreadCountOrDefault(options.num_threads);
  ceres::Solver::Summary summary;
  for (int pass = 0; pass < 2; ++pass) {
    ceres::Problem problem;
    for (size_t i = 0; i < n_points; ++i) {
      auto* functor = new TreePointResidual{&result.model,
                                            &parameters,
                                            {points[i].x(), points[i].y(), points[i].z()},
                                            {0, 0, 0},
                                            has_normals,
                                            options.normal_weight,
                                            h,
                                            &constant};
      if (has_normals)
        for (int k = 0; k < 3; ++k) functor->n[k] = normals[i][k];
      auto* cost = new ceres::DynamicAutoDiffCostFunction<TreePointResidual, 8>(functor);
      for (int size : parameters.block_sizes()) cost->AddParameterBlock(size);
      cost->SetNumResiduals(has_normals ? 4 : 1);
      problem.AddResidualBlock(cost, new ceres::CauchyLoss(loss_scale), block_ptrs);
    }
    parameters.Configure(&problem);
    ceres::Solver::Options solver_options;
    solver_options.linear_solver_type = ceres::DENSE_QR;
    solver_options.max_num_iterations = options.max_iterations;
    solver_options.num_threads = threads;
    ceres::Solve(solver_options, &problem, &summary);
    result.iterations += static_cast<int>(summary.iterations.size());
    std::vector<double> d = residual_distances(parameters.ToFlat());
    for (double& v : d) v = std::abs(v);
    result.sigma = 1.4826 * Median(d);
    loss_scale = std::max(2.0 * result.sigma, 1e-12);
    if (pass == 0) parameters.RestartCollapsedEpsilons(0.05);
  }

  result.model.mutable_parameters() = parameters.ToFlat();
  const std::vector<double> d = residual_distances(result.model.parameters());
  double ss = 0, angles = 0;
  for (size_t i = 0; i < n_points; ++i) {
    if (std::abs(d[i]) > 3.0 * result.sigma) continue;  // sigma 0 (exact data): |d| = 0 counts
    ++result.inliers;
    result.inlier_points.push_back(static_cast<int>(i));
    ss += d[i] * d[i];
    if (has_normals) {
      const Eigen::Vector3d g = result.model.Gradient(points[i]).normalized();
      angles += std::acos(std::min(1.0, std::abs(g.dot(normals[i])))) * 180.0 / M_PI;
    }
  }
  result.rms = result.inliers ? std::sqrt(ss / result.inliers) : 0.0;
  if (has_normals && result.inliers) result.mean_normal_angle_deg = angles / result.inliers;
  result.success = summary.IsSolutionUsable() && summary.termination_type == ceres::CONVERGENCE &&
                   result.inliers > 0;
  result.message = result.success ? "converged"
                   : result.inliers == 0 && summary.IsSolutionUsable() &&
                           summary.termination_type == ceres::CONVERGENCE
                       ? "no point lies within 3 sigma of the fitted model (0 inliers)"
                       : "solver did not converge: " + summary.message;
  result.termination = result.success ? FitTermination::kConverged
                       : summary.termination_type == ceres::NO_CONVERGENCE
                           ? FitTermination::kNoConvergence
                           : FitTermination::kFailure;
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace implicitfit
