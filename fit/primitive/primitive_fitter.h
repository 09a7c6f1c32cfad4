// Robust fitting of one primitive (plane, sphere, cylinder, cone, torus) to an oriented cloud.
//
// 1. Hypotheses from minimal samples of oriented points (fit/primitive/minimal_samples.h), drawn with a
//    seeded RNG, scored on a subsample: a point supports a hypothesis when |f| < tau and, when
//    normals are given, |cos(grad f, n)| >= normal_cos (sign-agnostic: unoriented normals work).
//    tau is `threshold` when given, else `start_band`, else 1% of the bounding-box diagonal.
// 2. Robust refinement to the maximum-likelihood fit on the inliers: least squares of the
//    orthogonal distances f(x_i) (every primitive's f is an exact signed distance) over the
//    current inlier set, in Ceres with closed-form derivatives (fit/primitive/primitive_jacobians.h), each
//    chunk of points one residual block of P + 1 residuals with the same normal equations
//    (fit/primitive/compressed_distance_cost.h);
//    then (adaptive band, the default) the noise scale is re-estimated as sigma = 1.4826 median
//    |f| of the inliers and the inlier band reset to |f| < band_sigmas * sigma; with a fixed
//    `threshold` the band stays |f| < threshold (Open3D's segment_plane distance_threshold,
//    PCL's setDistanceThreshold); repeated until the inlier set is stable, first on a random
//    working subset of the points, then on all of them.
//    Axes and normals live on ceres::SphereManifold<3>; radii are bounded below by 0 and the
//    cone angle to (0, pi/2) inside the solver (never clipped afterwards).
// Without normals (a coordinate-measuring machine's points, or estimated normals the reader did
// not trust: datasets/normals/normal_trust.h) the hypotheses come from k points alone
// (fit/metrology/point_hypotheses.h, k the free parameter count), every k-subset when there are at most
// `hypotheses` of them, and k + 1 inliers suffice. options.estimator then sets the final
// criterion over every point (fit/primitive/estimator.h).
// 3. Parameter standard deviations from ceres::Covariance at the solution, scaled by the
//    residual variance RSS / (N - dof).
// Everything is computed in a frame centred on the cloud's centroid, so UTM-sized coordinates
// lose no precision; results are returned in the input frame.
#pragma once

#include <Eigen/Core>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "fit/primitive/estimator.h"
#include "fit/common/fit_summary.h"
#include "fit/metrology/least_squares_fit.h"
#include "fit/metrology/minimum_zone.h"
#include "model/model.h"

namespace implicitfit {

struct PrimitiveFitOptions {
  NodeType kind = NodeType::kSphere;  // plane, sphere, cylinder, cone or torus
  unsigned seed = 1;                  // RNG seed: the fit is deterministic for a given seed
  int hypotheses = 400;               // most minimal-sample hypotheses tried
  int min_hypotheses = 30;            // fewest tried (adaptive stopping below)
  double confidence = 0.999;          // stop once an all-inlier sample was drawn this surely
  int score_subsample = 2000;         // points used to score hypotheses
  int working_subsample = 5000;       // points of the coarse refinement rounds
  // Inlier band. threshold > 0: a fixed inlier distance |f| < threshold in every round (the
  // meaning Open3D and PCL give it). Otherwise adaptive: start_band (> 0; else 1% of the bbox
  // diagonal) for the hypotheses and the first round, then band_sigmas * the estimated sigma.
  double threshold = 0.0;
  double start_band = 0.0;
  double normal_cos = 0.8;            // inlier normal agreement |cos| (used when normals exist)
  double band_sigmas = 3.0;           // final inlier band in units of the estimated sigma
  int max_rounds = 8;                 // refit / re-classify rounds
  double stable_fraction = 0.002;     // inlier set "stable" when at most this fraction changed
  int min_inliers = 20;               // fewer: the fit fails (from points alone: k + 1)
  double min_inlier_fraction = 0.02;  // fewer than this fraction of the points: the fit fails
  int num_threads = 0;                // Ceres threads; 0 = hardware concurrency
  bool compute_covariance = true;     // parameter standard deviations
  std::map<std::string, std::vector<double>> fixed;  // field name -> value kept constant
  Estimator estimator = Estimator::kRobust;          // final criterion (fit/primitive/estimator.h)
  std::vector<double> initial;  // non-empty: no hypotheses, refine from these parameters

  // False (with a reason) for an invalid combination.
  bool IsValid(std::string* error) const;
};

// termination: CONVERGENCE when the last round's solve converged on a stable inlier set;
// NO_CONVERGENCE when the solve hit its iteration limit (success false) or max_rounds ran out
// before the inlier set was stable (success true: the result of the last round is usable);
// FAILURE otherwise.
struct PrimitiveFitResult : FitSummary {
  NodeType kind = NodeType::kSphere;        // the kind fitted (options.kind)
  std::vector<double> parameters;           // flat layout of the model evaluator (model/*.h)
  std::vector<double> standard_deviations;  // same layout; empty when not computed
  std::vector<int> inliers;                 // indices into the input cloud
  double sigma = 0.0;                       // estimated noise scale (1.4826 MAD)
  double rms = 0.0, max_abs = 0.0;          // of the inliers' distances
  double mean_normal_angle_deg = -1.0;      // mean angle between grad f and the inliers' normals
  int iterations = 0;                       // Ceres iterations, all rounds
  int rounds = 0;
  bool points_only = false;                  // hypotheses from points alone (no normals given)
  Estimator estimator = Estimator::kRobust;  // which estimator produced `parameters`
  FormFigures form;                          // every point's distances to the result
  double final_step = 0.0;                   // least-squares: last Gauss-Newton step length
  MinimumZoneResult zone;                    // minimum-zone: width, contacts, multipliers

  // The fitted primitive as a one-node model.
  Model ToModel(NodeType kind) const;
  // "points N  inliers M  rms ...  s" and "estimator ... form error ..." (two lines).
  std::string BriefReport() const;
  // The report of fit/common/fit_report.h; `normals` says where the normals came from.
  nlohmann::json ToJson(const std::string& normals) const;
};

// points: the cloud; normals: empty or one per point.
PrimitiveFitResult FitPrimitive(const std::vector<Eigen::Vector3d>& points,
                                const std::vector<Eigen::Vector3d>& normals,
                                const PrimitiveFitOptions& options);

// "plane" -> kPlane ... for the fittable kinds (fit/primitive/fittable_primitives.h); false otherwise.
bool FittableKindFromName(const std::string& name, NodeType* kind);
// Their names, "plane, sphere, cylinder, cone, torus", for messages.
std::string FittableKindNames();

}  // namespace implicitfit
