#include "fit/primitive/primitive_fitter.h"

#include <ceres/ceres.h>
#include <ceres/context.h>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numeric>
#include <random>

#include "fit/primitive/estimator_stage.h"
#include "fit/primitive/fittable_primitives.h"
#include "fit/metrology/point_hypotheses.h"
#include "fit/primitive/primitive_fit_stages.h"
#include "fit/metrology/primitive_tangent.h"
#include "fit/common/thread_count.h"
#include "model/primitives/primitive_kinds.h"

namespace implicitfit {
namespace {

// Normalises the direction (and the plane offset with it) and puts the axis point of a
// cylinder at the foot of the origin (the recentred cloud's centroid).
void Canonicalise(NodeType kind, std::vector<double>* p) {
  const std::vector<ParameterField>& fields = ParameterFieldsOf(kind);
  int dir = 0, k = 0;
  if (!FindFieldWithRole(fields, FieldRole::kDirection, &dir)) return;
  Eigen::Map<Eigen::Vector3d> a(p->data() + dir);
  const double n = a.norm();
  a /= n;
  for (const ParameterField& f : fields) {
    if (f.role == FieldRole::kPlaneOffset) (*p)[k] /= n;
    if (f.role == FieldRole::kAxisPoint) {
      Eigen::Map<Eigen::Vector3d> q(p->data() + k);
      q -= a * a.dot(q);
    }
    k += f.size;
  }
}

// The whole fit in the recentred frame (fit/primitive/primitive_fit_stages.h), then moved back.
PrimitiveFitResult Fit(const std::vector<Eigen::Vector3d>& input_points,
                       const std::vector<Eigen::Vector3d>& normals,
                       const PrimitiveFitOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  PrimitiveFitResult result;
  const NodeType kind = options.kind;
  const size_t N = input_points.size();
  const bool has_normals = !normals.empty();

  const RecentredCloud cloud = Recentre(input_points);
  const std::vector<Eigen::Vector3d>& pts = cloud.points;
  const double tau = options.threshold > 0    ? options.threshold
                     : options.start_band > 0 ? options.start_band
                                              : 0.01 * cloud.diagonal;

  // Without normals: hypotheses from points alone (fit/metrology/point_hypotheses.h).
  result.points_only = !has_normals;
  if (!has_normals) {
    result.message = PointSetDegeneracy(kind, pts);
    if (!FindFittablePrimitive(kind)->from_points && result.message.empty())
      result.message = std::string("a ") + NodeTypeName(kind) +
                       " needs normals: it is not hypothesised from points alone";
    if (!result.message.empty()) return result;
  }
  const std::vector<double> fixed_values = FixedInRecentred(kind, options.fixed, cloud.centroid);

  std::mt19937 rng(options.seed);
  HypothesisSearchResult start_point =
      FindHypothesis(cloud, normals, tau, options, fixed_values, rng);
  if (start_point.parameters.empty()) {
    result.message = start_point.message;
    return result;
  }
  std::vector<double> params = std::move(start_point.parameters);

  // Coarse rounds run on a random working subset (the inlier set and scale settle there at a
  // fraction of the cost); the final rounds use every point. options.max_rounds bounds the
  // rounds of both together: the coarse ones stop one round early so that at least one round
  // runs on every point.
  std::vector<int> all(N);
  std::iota(all.begin(), all.end(), 0);
  std::vector<int> working = all;
  const bool subset = N > static_cast<size_t>(options.working_subsample);
  if (subset) {
    for (size_t i = 0; i < static_cast<size_t>(options.working_subsample); ++i) {
      std::uniform_int_distribution<size_t> pick(i, N - 1);
      std::swap(working[i], working[pick(rng)]);
    }
    working.resize(options.working_subsample);
    std::sort(working.begin(), working.end());
  }
  bool final_stage = !subset || options.max_rounds == 1;
  const std::vector<int>* pool = final_stage ? &all : &working;
  double band = tau;
  std::vector<int> inliers = Classify(kind, params, pts, normals, *pool, band, options.normal_cos);
  // One Ceres context (its thread pool) for every round's problem, instead of one per problem.
  std::unique_ptr<ceres::Context> context(ceres::Context::Create());
  RefinementRound round;
  const int threads = ThreadCountOrDefault(options.num_threads);
  bool settled = false;  // the inlier set of every point stopped changing
  for (int r = 0; r < options.max_rounds; ++r) {
    const size_t floor = has_normals ? options.min_inliers : FreeParameterCount(kind) + 1;
    const size_t min_needed = std::max<size_t>(floor, options.min_inlier_fraction * pool->size());
    if (inliers.size() < min_needed && options.estimator != Estimator::kRobust) {
      // Least squares and minimum zone use every point afterwards (fit/primitive/estimator_stage.h): the
      // robust rounds only give them a start, which a short inlier set ends instead of failing
      // (6 exact points on a cylinder: one can fall outside the band of an early iterate).
      if (round.problem) {
        settled = true;  // the inlier set plays no part in what follows
        break;
      }
      inliers = *pool;
    }
    if (inliers.size() < min_needed) {
      result.message = "too few inliers: " + std::to_string(inliers.size()) + " of " +
                       std::to_string(N) + " points (need " + std::to_string(min_needed) + ")";
      result.parameters = params;
      TranslatePrimitive(kind, cloud.centroid, &result.parameters);
      return result;
    }
    SolveRound(kind, pts, inliers, options.fixed, threads, context.get(), &params, &round);
    result.iterations += static_cast<int>(round.summary.iterations.size());
    result.rounds = r + 1;
    Reclassification next = Reclassify(kind, params, pts, normals, *pool, inliers, options);
    result.sigma = next.sigma;
    band = next.band;
    inliers = std::move(next.inliers);
    const bool last_coarse = !final_stage && r + 2 >= options.max_rounds;
    if (next.stable || last_coarse) {
      if (final_stage) {
        settled = next.stable;
        break;
      }
      final_stage = true;  // switch to every point
      pool = &all;
      inliers = Classify(kind, params, pts, normals, all, band, options.normal_cos);
    }
  }

  result.inliers = inliers;
  const InlierFigures figures = Figures(kind, params, pts, normals, inliers);
  result.rms = figures.rms;
  result.max_abs = figures.max_abs;
  result.mean_normal_angle_deg = figures.mean_normal_angle_deg;
  if (options.compute_covariance && round.problem)
    result.standard_deviations =
        StandardDeviations(kind, &round, options.fixed, figures.rss, inliers.size(), threads);

  Canonicalise(kind, &params);
  TranslatePrimitive(kind, cloud.centroid, &params);
  result.parameters = params;
  const ceres::Solver::Summary& summary = round.summary;
  const bool converged = summary.termination_type == ceres::CONVERGENCE;
  result.success = converged && summary.IsSolutionUsable();
  result.message = converged ? "converged" : "solver did not converge: " + summary.message;
  if (summary.termination_type == ceres::NO_CONVERGENCE)
    result.termination = FitTermination::kNoConvergence;
  else if (result.success && settled)
    result.termination = FitTermination::kConverged;
  else if (result.success) {  // usable: the last round's solve converged
    result.termination = FitTermination::kNoConvergence;
    result.message = "no convergence within " + std::to_string(options.max_rounds) +
                     " rounds: the inlier set still changed";
  }
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace

bool PrimitiveFitOptions::IsValid(std::string* error) const {
  auto fail = [error](const std::string& e) {
    if (error) *error = e;
    return false;
  };
  const NodeType k = kind;
  if (!FindFittablePrimitive(k))
    return fail(std::string("cannot fit a ") + NodeTypeName(k) + " with the primitive fitter");
  if (hypotheses < 1 || min_hypotheses < 1)
    return fail("hypotheses and min_hypotheses must be >= 1");
  if (!(confidence > 0 && confidence < 1)) return fail("confidence must be in (0, 1)");
  if (!initial.empty() && static_cast<int>(initial.size()) != NumParametersOf(k))
    return fail("initial parameters: " + std::to_string(initial.size()) + " values, a " +
                NodeTypeName(k) + " has " + std::to_string(NumParametersOf(k)));
  if (!(threshold >= 0) || !std::isfinite(threshold) || !(start_band >= 0) ||
      !std::isfinite(start_band))
    return fail("threshold and start_band must be >= 0 and finite");
  if (threshold > 0 && start_band > 0)
    return fail("a fixed threshold and an adaptive start band exclude each other");
  if (score_subsample < 10 || working_subsample < 10)
    return fail("subsamples must hold >= 10 points");
  if (!(normal_cos >= 0 && normal_cos <= 1)) return fail("normal_cos must be in [0, 1]");
  if (!(band_sigmas > 0)) return fail("band_sigmas must be > 0");
  if (max_rounds < 1) return fail("max_rounds must be >= 1");
  for (const auto& [name, value] : fixed) {
    bool known = false;
    for (const ParameterField& f : ParameterFieldsOf(k))
      if (name == f.name) {
        known = true;
        if (static_cast<int>(value.size()) != f.size)
          return fail("fixed field " + name + " takes " + std::to_string(f.size) + " value(s)");
      }
    if (!known)
      return fail("fixed field '" + name + "' is not a parameter of a " + NodeTypeName(k));
  }
  return true;
}

Model PrimitiveFitResult::ToModel(NodeType kind) const {
  Model m;
  m.AddPrimitive(kind, parameters);
  return m;
}

bool FittableKindFromName(const std::string& name, NodeType* kind) {
  for (const FittablePrimitive& k : FittablePrimitives())
    if (name == NodeTypeName(k.type)) {
      *kind = k.type;
      return true;
    }
  return false;
}

std::string FittableKindNames() {
  std::string names;
  for (const FittablePrimitive& kind : FittablePrimitives())
    names += (names.empty() ? "" : ", ") + std::string(NodeTypeName(kind.type));
  return names;
}

namespace {

// Rank check before any fit: a plane needs points not all on one line, the curved kinds points
// not all in one plane (a circle of points is on infinitely many spheres, cylinders, cones),
// and every kind at least as many distinct points as it has degrees of freedom (one more without
// normals: the points alone then give the hypotheses, fit/metrology/point_hypotheses.h). Fixed
// parameters lower what is needed: then only a non-degenerate set is asked for. The rank is
// that of the centred points: singular values below 1e-9 of the largest count as zero.
bool DeterminesPrimitive(const std::vector<Eigen::Vector3d>& points, bool has_normals,
                         const PrimitiveFitOptions& options, std::string* message) {
  const char* name = NodeTypeName(options.kind);
  const bool plane = options.kind == NodeType::kPlane;
  const bool fixed = !options.fixed.empty();
  const int dof = plane                                 ? 3
                  : options.kind == NodeType::kSphere   ? 4
                  : options.kind == NodeType::kCylinder ? 5
                  : options.kind == NodeType::kCone     ? 6
                                                        : 7;
  std::vector<Eigen::Vector3d> sorted = points;
  std::sort(sorted.begin(), sorted.end(), [](const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
    return std::lexicographical_compare(a.data(), a.data() + 3, b.data(), b.data() + 3);
  });
  const size_t distinct = std::unique(sorted.begin(), sorted.end()) - sorted.begin();
  const size_t needed = fixed ? 2 : static_cast<size_t>(dof + (has_normals ? 0 : 1));
  if (distinct < needed) {
    *message = std::to_string(distinct) + " distinct point" + (distinct == 1 ? "" : "s") +
               " (of " + std::to_string(points.size()) + "): a " + name + " needs at least " +
               std::to_string(needed) + " points";
    return false;
  }
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (size_t i = 0; i < distinct; ++i) mean += sorted[i];
  mean /= static_cast<double>(distinct);
  Eigen::Matrix3d scatter = Eigen::Matrix3d::Zero();
  for (size_t i = 0; i < distinct; ++i) scatter += (sorted[i] - mean) * (sorted[i] - mean).transpose();
  const Eigen::Vector3d s = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(scatter)
                                .eigenvalues()
                                .cwiseMax(0.0)
                                .cwiseSqrt();  // ascending singular values
  int rank = 0;
  for (int k = 0; k < 3; ++k) rank += s[k] > 1e-9 * s[2];
  const int needed_rank = fixed ? 1 : plane ? 2 : 3;
  if (rank < needed_rank) {
    *message = std::string(rank <= 1 ? "the points are collinear" : "the points are coplanar") +
               " (rank " + std::to_string(rank) + "): they do not determine a " + name;
    return false;
  }
  return true;
}

}  // namespace

PrimitiveFitResult FitPrimitive(const std::vector<Eigen::Vector3d>& points,
                                const std::vector<Eigen::Vector3d>& normals,
                                const PrimitiveFitOptions& options) {
  PrimitiveFitResult result;
  result.kind = options.kind;
  result.points = points.size();
  std::string error;
  if (!options.IsValid(&error)) {
    result.message = error;
    return result;
  }
  if (points.size() < 3) {
    result.message = "too few points: " + std::to_string(points.size());
    return result;
  }
  if (!normals.empty() && normals.size() != points.size()) {
    result.message = "normals and points differ in count";
    return result;
  }
  if (!DeterminesPrimitive(points, !normals.empty(), options, &result.message)) return result;
  result = Fit(points, normals, options);
  result.kind = options.kind;
  result.points = points.size();
  FinishWithEstimator(points, options, &result);
  if (!result.success && result.termination == FitTermination::kConverged)
    result.termination = FitTermination::kFailure;  // the estimator stage failed
  return result;
}

}  // namespace implicitfit
