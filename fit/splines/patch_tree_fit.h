// Fitting the placements of a patch tree (model/splines/patch_tree.h, docs/maths.md JE-1) to a
// cloud by orthogonal distance, as bundle adjustment: unknowns the links' placement numbers
// (a, b, c, d, theta; those not `free` held by a subset manifold) and one (s_k, t_k) per point in
// the root's domain box; residual G(s_k, t_k) - x_k (3-vector, automatic derivatives through
// the blend weights). Ceres, DENSE_SCHUR with the point blocks in elimination group 0 (the
// reduced system is the placements' own, 5 per link). Start: each point's (s_k, t_k) is the
// nearest of a 96 x 96 sampling of G over the root's domain box, refined by Gauss-Newton steps
// on |G(s, t) - x_k|^2 (Dual3 derivatives).
#pragma once

#include <Eigen/Core>
#include <vector>

#include "fit/common/fit_summary.h"
#include "model/splines/patch_tree.h"

namespace implicitfit {

struct PatchTreeFitOptions {
  // Per link, which of (a, b, c, d, theta) are fitted; default a, b, theta.
  std::vector<std::vector<bool>> free;
  int max_iterations = 100;
  int num_threads = 0;
};

struct PatchTreeFitResult : FitSummary {
  std::vector<double> placements;
  std::vector<Eigen::Vector2d> parameters;  // (s_k, t_k)
  double rms = 0.0, initial_rms = 0.0;      // RMS |G(s_k, t_k) - x_k|
  int iterations = 0;
};

PatchTreeFitResult FitPatchTreePlacements(const PatchTree& start,
                                          const std::vector<Eigen::Vector3d>& points,
                                          const PatchTreeFitOptions& options = {});

}  // namespace implicitfit
