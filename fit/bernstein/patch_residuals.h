// The residuals and solver plumbing shared by the Bernstein patch fits (fit/bernstein/patch_fitter.h
// and the convex fits of fit/bernstein/convex_patch_fit.h).
//
// Per point p_i with outward normal n_i (optional): the first-order geometric distance
// r_0 = f / |grad f| and the signed normal term w (grad f / |grad f| - n_i), grad f analytic
// (de Casteljau), one residual block per point under a Cauchy loss of scale `loss_scale`:
//   cost = sum_i rho(|r_i|^2),  rho(s) = c^2 log(1 + s / c^2)  (Ceres' 1/2 convention aside).
#pragma once

#include <ceres/ceres.h>

#include <Eigen/Core>
#include <string>
#include <vector>

#include "fit/common/fit_termination.h"
#include "model/bernstein/bernstein_patch.h"

namespace implicitfit {

// Geometric + normal residuals of one point, for the control points b (N of them).
template <int N>
struct PatchPointResidual {
  int degree;
  const Tetrahedron* tet;
  double x[3], n[3];
  bool has_normal;
  double w;
  template <typename T>
  bool operator()(const T* b, T* r) const {
    using std::sqrt;
    const T xt[3] = {T(x[0]), T(x[1]), T(x[2])};
    Eigen::Matrix<T, 3, 1> g;
    const T f = BernsteinPatch::Derivatives(degree, *tet, b, xt, &g);
    const T gn = sqrt(g.squaredNorm() + 1e-24);
    r[0] = f / gn;
    if (has_normal) {
      // Signed: grad f must point along the given (outward) normal, not merely be parallel to
      // it, so the fitted solid lies on the side the normals call inside (issue #12).
      for (int k = 0; k < 3; ++k) r[1 + k] = w * (g[k] / gn - n[k]);
    }
    return true;
  }
};

template <int N>
PatchPointResidual<N> MakePointResidual(int k, const Tetrahedron& tet,
                                        const std::vector<Eigen::Vector3d>& points,
                                        const std::vector<Eigen::Vector3d>& normals, size_t i,
                                        double w) {
  PatchPointResidual<N> r{
      k, &tet, {points[i].x(), points[i].y(), points[i].z()}, {0, 0, 0}, !normals.empty(), w};
  if (!normals.empty())
    for (int c = 0; c < 3; ++c) r.n[c] = normals[i][c];
  return r;
}

// One block per point (1 residual, or 4 with the normal term) with a Cauchy loss, on `block`.
template <typename Functor, int N, typename Make>
void AddPointBlocks(ceres::Problem* problem, size_t count, bool with_normals, const Make& make,
                    double loss_scale, double* block) {
  for (size_t i = 0; i < count; ++i) {
    Functor* f = new Functor(make(i));
    ceres::CostFunction* cost =
        with_normals
            ? static_cast<ceres::CostFunction*>(new ceres::AutoDiffCostFunction<Functor, 4, N>(f))
            : new ceres::AutoDiffCostFunction<Functor, 1, N>(f);
    problem->AddResidualBlock(cost, new ceres::CauchyLoss(loss_scale), block);
  }
}

// Dense QR Levenberg-Marquardt, two threads.
ceres::Solver::Summary SolvePatchProblem(ceres::Problem* problem, int max_iterations);

// What a solve ended with (fit/common/fit_termination.h) and a message saying so.
struct SolveOutcome {
  FitTermination termination = FitTermination::kFailure;
  std::string message;
};
SolveOutcome DescribeSolve(const ceres::Solver::Summary& summary);

// RMS of f / |grad f| over the points; the mean angle (deg) and mean signed cosine between
// grad f and the normals (-1 and 0 without normals).
double PatchRms(int k, const Tetrahedron& tet, const std::vector<double>& b,
                const std::vector<Eigen::Vector3d>& points,
                const std::vector<Eigen::Vector3d>& normals, double* mean_angle,
                double* mean_cosine = nullptr);

}  // namespace implicitfit
