// The stages of the primitive fitter (fit/primitive/primitive_fitter.h), each a function of its inputs so
// that each can be tested on its own. FitPrimitive runs them in this order:
//   Recentre            the cloud moved to its centroid (precision with UTM-sized coordinates)
//   FixedInRecentred    options.fixed in that frame (positions moved, the plane offset too)
//   FindHypothesis      the start: options.initial, or the best of the minimal-sample
//                       hypotheses (adaptive RANSAC stopping), or from points alone
//   Classify            the inlier set: |f| < limit and |cos(grad f, n)| >= normal_cos
//   SolveRound          one refinement round: Ceres least squares of the inliers' distances
//   Reclassify          the noise scale sigma = 1.4826 median |f| of the inliers, the band
//                       band_sigmas * sigma, the new inlier set and whether it is stable
//   Figures             RMS, largest |f| and mean normal angle of the inliers
//   StandardDeviations  ceres::Covariance of the last round, scaled by RSS / (N - dof)
// Every function works in the recentred frame on the kind's flat parameters (model/*.h) and
// reads the kind's fields and roles from model/primitives/primitive_kinds.h.
#pragma once

#include <ceres/ceres.h>

#include <Eigen/Core>
#include <map>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "fit/primitive/primitive_fitter.h"

namespace implicitfit {

struct RecentredCloud {
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  std::vector<Eigen::Vector3d> points;  // input - centroid
  double diagonal = 0.0;                // of the axis-aligned bounding box
};
RecentredCloud Recentre(const std::vector<Eigen::Vector3d>& points);

// The fixed values (options.fixed) in the frame centred on `centroid`, in the kind's flat
// layout; NaN where a parameter is free.
std::vector<double> FixedInRecentred(NodeType kind,
                                     const std::map<std::string, std::vector<double>>& fixed,
                                     const Eigen::Vector3d& centroid);
// Overwrites the fixed entries (not NaN) of *params.
void ApplyFixed(const std::vector<double>& fixed_values, std::vector<double>* params);

struct HypothesisSearchResult {
  std::vector<double> parameters;  // empty when no valid hypothesis was found
  std::string message;             // why not
  int tried = 0;                   // minimal samples drawn (or point subsets tried)
};
// The start of the refinement, recentred: options.initial moved into the frame; else with
// normals the hypothesis of most support on a subsample of options.score_subsample points
// over options.min_hypotheses..options.hypotheses minimal samples (stopping once one free of
// outliers was drawn with probability options.confidence); without normals the best from
// points alone (fit/metrology/point_hypotheses.h). Fixed values are applied to every hypothesis.
HypothesisSearchResult FindHypothesis(const RecentredCloud& cloud,
                                      const std::vector<Eigen::Vector3d>& normals, double tau,
                                      const PrimitiveFitOptions& options,
                                      const std::vector<double>& fixed_values, std::mt19937& rng);

// The indices of `pool` whose point has |f| < limit and |cos(grad f, n)| >= normal_cos (normals
// empty: distance only).
std::vector<int> Classify(NodeType kind, const std::vector<double>& params,
                          const std::vector<Eigen::Vector3d>& points,
                          const std::vector<Eigen::Vector3d>& normals, const std::vector<int>& pool,
                          double limit, double normal_cos);

// One refinement round: the problem (one block per field, directions on SphereManifold<3>,
// positive lengths and angles bounded, fields in `fixed` constant), kept for the covariance.
struct RefinementRound {
  std::vector<std::vector<double>> blocks;
  std::unique_ptr<ceres::Problem> problem;
  ceres::Solver::Summary summary;
};
// Least squares of the distances of the inliers from *params (updated). context may be null.
void SolveRound(NodeType kind, const std::vector<Eigen::Vector3d>& points,
                const std::vector<int>& inliers,
                const std::map<std::string, std::vector<double>>& fixed, int num_threads,
                ceres::Context* context, std::vector<double>* params, RefinementRound* round);

struct Reclassification {
  double sigma = 0.0;  // 1.4826 median |f| of the old inliers
  double band = 0.0;   // the new inlier limit
  std::vector<int> inliers;
  bool stable = false;  // at most options.stable_fraction of the old inliers changed
};
// After a round: the scale from `inliers`, the new inlier set from `pool`. Without normals the
// band is at least band_sigmas times the residual standard error sqrt(RSS / (n - k)).
Reclassification Reclassify(NodeType kind, const std::vector<double>& params,
                            const std::vector<Eigen::Vector3d>& points,
                            const std::vector<Eigen::Vector3d>& normals,
                            const std::vector<int>& pool, const std::vector<int>& inliers,
                            const PrimitiveFitOptions& options);

struct InlierFigures {
  double rss = 0.0, rms = 0.0, max_abs = 0.0;
  double mean_normal_angle_deg = -1.0;  // -1 without normals
};
InlierFigures Figures(NodeType kind, const std::vector<double>& params,
                      const std::vector<Eigen::Vector3d>& points,
                      const std::vector<Eigen::Vector3d>& normals, const std::vector<int>& inliers);

// Standard deviations of the flat parameters from the last round's problem: the covariance
// (pseudo-inverse: the cylinder's axis point slides along its axis) scaled by
// rss / (inliers - dof); 0 for fixed fields; empty when the covariance is not computable.
std::vector<double> StandardDeviations(NodeType kind, RefinementRound* round,
                                       const std::map<std::string, std::vector<double>>& fixed,
                                       double rss, size_t inliers, int num_threads);

}  // namespace implicitfit
