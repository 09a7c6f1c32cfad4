// Fits every free parameter of a given model tree (fit --init): primitive parameters, delta and
// epsilon of every blend, control points of Bernstein patches; fields listed in a node's
// "fixed" are kept. Parameterisation: fit/tree/tree_parameters.h (0 < epsilon <= delta by
// construction, unit axes on SphereManifold<3>, positive radii). Residuals:
// fit/tree/tree_point_residual.h, one block per point with a Cauchy loss.
// Two passes: the first with the loss scale 1% of the cloud's bounding-box diagonal, then the
// noise scale sigma = 1.4826 median |r_0| and a second pass with the loss scale 2 sigma. A blend
// whose epsilon collapsed below 5% of delta in the first pass restarts the second at delta / 2
// (fit/tree/tree_parameters.h: RestartCollapsedEpsilons).
#pragma once

#include <Eigen/Core>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "fit/common/fit_summary.h"
#include "model/model.h"

namespace implicitfit {

// Largest rows x free parameters^2 (rows: 4 per point with normals, else 1) FitModelTree takes:
// a 2x2x2 plane partition (32 parameters) on 2000 oriented points, 8.2e6, took 1 s.
constexpr double kMaxTreeFitWork = 5e8;

struct TreeFitOptions {
  double normal_weight = 0.1;  // w of the normal residuals (units of distance per unit vector)
  int max_iterations = 200;    // Ceres iterations per pass
  int num_threads = 0;         // 0 = hardware concurrency
  // > 0: refuse (success false, with the figures) a fit whose dense cost rows x free
  // parameters^2 exceeds it; the command line passes kMaxTreeFitWork.
  double max_work = 0.0;
  // False (with a reason) for a negative or non-finite weight, fewer than 1 iteration or a
  // negative thread count.
  bool IsValid(std::string* error) const;
};

// termination: CONVERGENCE, NO_CONVERGENCE (the second pass hit max_iterations; success false)
// or FAILURE (bad options, too few points, nothing to fit, a failed solve).
struct TreeFitResult : FitSummary {
  Model model;         // the fitted tree (same structure as the initial one)
  double rms = 0.0;    // RMS geometric distance of the inliers (|r_0| < 3 sigma)
  double sigma = 0.0;  // robust noise scale
  int inliers = 0;
  std::vector<int> inlier_points;  // their indices into the points, ascending
  double mean_normal_angle_deg = -1.0;
  int iterations = 0;
  // "points N  inliers M  rms ...  s" (one line).
  std::string BriefReport() const;
  // The report of fit/common/fit_report.h; `normals` says where the normals came from.
  nlohmann::json ToJson(const std::string& normals) const;
};

TreeFitResult FitModelTree(const Model& initial, const std::vector<Eigen::Vector3d>& points,
                           const std::vector<Eigen::Vector3d>& normals,
                           const TreeFitOptions& options);

}  // namespace implicitfit
