#include "fit/bernstein/patch_residuals.h"

#include <algorithm>
#include <cmath>

namespace implicitfit {

ceres::Solver::Summary SolvePatchProblem(ceres::Problem* problem, int max_iterations) {
  ceres::Solver::Options so;
  so.linear_solver_type = ceres::DENSE_QR;
  so.max_num_iterations = max_iterations;
  so.num_threads = 2;
  ceres::Solver::Summary summary;
  ceres::Solve(so, problem, &summary);
  return summary;
}

SolveOutcome DescribeSolve(const ceres::Solver::Summary& summary) {
  switch (summary.termination_type) {
    case ceres::CONVERGENCE:
    case ceres::USER_SUCCESS:
      return {FitTermination::kConverged, "converged"};
    case ceres::NO_CONVERGENCE:
      return {
          FitTermination::kNoConvergence,
          "no convergence within " +
              std::to_string(std::max<int>(0, static_cast<int>(summary.iterations.size()) - 1)) +
              " iterations (the iteration limit): " + summary.message};
    case ceres::FAILURE:
    case ceres::USER_FAILURE:
      break;
  }
  return {FitTermination::kFailure, summary.message};
}

double PatchRms(int k, const Tetrahedron& tet, const std::vector<double>& b,
                const std::vector<Eigen::Vector3d>& points,
                const std::vector<Eigen::Vector3d>& normals, double* mean_angle,
                double* mean_cosine) {
  double ss = 0, angles = 0, cosines = 0;
  for (size_t i = 0; i < points.size(); ++i) {
    Eigen::Vector3d g;
    const double f = BernsteinPatch::Derivatives(k, tet, b.data(), points[i].data(), &g);
    ss += f * f / std::max(g.squaredNorm(), 1e-300);
    if (!normals.empty()) {
      const double cosine = std::clamp(g.normalized().dot(normals[i]), -1.0, 1.0);  // signed
      angles += std::acos(cosine) * 180 / M_PI;
      cosines += cosine;
    }
  }
  if (mean_angle) *mean_angle = normals.empty() ? -1.0 : angles / points.size();
  if (mean_cosine) *mean_cosine = normals.empty() ? 0.0 : cosines / points.size();
  return std::sqrt(ss / points.size());
}

}  // namespace implicitfit
