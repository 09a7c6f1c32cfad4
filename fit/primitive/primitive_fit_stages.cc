#include "fit/primitive/primitive_fit_stages.h"

#include <ceres/covariance.h>
#include <ceres/sphere_manifold.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <numeric>

#include "fit/primitive/compressed_distance_cost.h"
#include "fit/primitive/fittable_primitives.h"
#include "fit/metrology/point_hypotheses.h"
#include "fit/metrology/primitive_tangent.h"
#include "model/median.h"
#include "model/primitives/primitive_kinds.h"

namespace implicitfit {
namespace {

// Points per residual block (fit/primitive/compressed_distance_cost.h).
constexpr size_t kChunk = 4096;
// Solver stops when the next step would move the parameters by less than this many standard
// deviations (see the function tolerance in SolveRound).
constexpr double kStepSd = 0.05;

// |cos(g, n)|, 0 for a zero gradient.
double NormalCos(const double* g, const Eigen::Vector3d& n) {
  const double gn = std::sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]);
  return gn > 0 ? std::abs(g[0] * n[0] + g[1] * n[1] + g[2] * n[2]) / gn : 0.0;
}

// True when |f(x)| < limit and |cos(grad f(x), n)| >= min_cos.
template <typename E>
bool Supports(const PrimitiveDistance<E>& f, const Eigen::Vector3d& x, const Eigen::Vector3d& n,
              double limit, double min_cos) {
  double g[3];
  if (!(std::abs(f(x.data(), nullptr, g)) < limit)) return false;
  return NormalCos(g, n) >= min_cos;
}

// Makes the first k entries of *v a uniformly random k-subset of its entries (the first k steps
// of Fisher-Yates): O(k) instead of shuffling all of v.
template <typename T>
void PartialShuffle(std::vector<T>* v, size_t k, std::mt19937& rng) {
  const size_t n = v->size();
  for (size_t i = 0; i < std::min(k, n); ++i) {
    std::uniform_int_distribution<size_t> pick(i, n - 1);
    std::swap((*v)[i], (*v)[pick(rng)]);
  }
}

// acos(c) for c in [0, 1] within 2.2e-8 rad (1.3e-6 degrees): sqrt(1 - c) times a degree-7
// polynomial (Abramowitz & Stegun 4.4.46), a fraction of std::acos' cost for the mean normal
// angle over every inlier.
double AcosUnit(double c) {
  double q = -0.0012624911;
  for (double a : {0.0066700901, -0.0170881256, 0.0308918810, -0.0501743046, 0.0889789874,
                   -0.2145988016, 1.5707963050})
    q = q * c + a;
  return std::sqrt(1.0 - c) * q;
}

// The best minimal-sample hypothesis on the subsample `sub` (adaptive RANSAC stopping: after t
// draws with best inlier ratio w, a sample of m points free of outliers was drawn with
// probability 1 - (1 - w^m)^t; stop once that reaches options.confidence, and after at least
// options.min_hypotheses).
template <typename E>
std::vector<double> RansacHypothesis(const FittablePrimitive& entry,
                                     const std::vector<Eigen::Vector3d>& pts,
                                     const std::vector<Eigen::Vector3d>& normals,
                                     const std::vector<size_t>& sub, double tau,
                                     const PrimitiveFitOptions& options,
                                     const std::vector<double>& fixed_values, std::mt19937& rng) {
  const int m = entry.sample_size;
  std::uniform_int_distribution<size_t> pick(0, pts.size() - 1);
  std::vector<Vec3> p(m), n(m);
  std::vector<size_t> idx(m);
  std::vector<double> best, h;
  int best_score = -1, needed = options.hypotheses;
  for (int t = 0; t < needed; ++t) {
    for (int s = 0; s < m; ++s) idx[s] = pick(rng);
    bool distinct = true;  // a repeated point makes a degenerate sample
    for (int s = 1; s < m; ++s)
      distinct &= std::find(idx.begin(), idx.begin() + s, idx[s]) == idx.begin() + s;
    if (!distinct) continue;
    for (int s = 0; s < m; ++s) {
      p[s] = pts[idx[s]];
      n[s] = normals[idx[s]];
    }
    if (!entry.from_sample(p.data(), n.data(), &h)) continue;
    ApplyFixed(fixed_values, &h);
    const PrimitiveDistance<E> hf(h.data());
    int score = 0;
    for (size_t i : sub) score += Supports(hf, pts[i], normals[i], tau, options.normal_cos);
    if (score > best_score) {
      best_score = score;
      best = h;
      const double w = std::min(0.999, static_cast<double>(score) / sub.size());
      const double k = std::log(1.0 - options.confidence) / std::log(1.0 - std::pow(w, m));
      if (std::isfinite(k))  // clamped as a double: k reaches 1e13 when w is small (UBSan)
        needed = static_cast<int>(
            std::clamp(std::ceil(k), double(options.min_hypotheses), double(options.hypotheses)));
    }
  }
  return best;
}

}  // namespace

RecentredCloud Recentre(const std::vector<Eigen::Vector3d>& points) {
  RecentredCloud cloud;
  const size_t n = points.size();
  for (const auto& p : points) cloud.centroid += p;
  if (n > 0) cloud.centroid /= static_cast<double>(n);
  cloud.points.resize(n);
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(INFINITY), hi = -lo;
  for (size_t i = 0; i < n; ++i) {
    cloud.points[i] = points[i] - cloud.centroid;
    lo = lo.cwiseMin(cloud.points[i]);
    hi = hi.cwiseMax(cloud.points[i]);
  }
  cloud.diagonal = n > 0 ? (hi - lo).norm() : 0.0;
  return cloud;
}

std::vector<double> FixedInRecentred(NodeType kind,
                                     const std::map<std::string, std::vector<double>>& fixed,
                                     const Eigen::Vector3d& centroid) {
  const std::vector<ParameterField>& fields = ParameterFieldsOf(kind);
  std::vector<double> values(NumParametersOf(kind), NAN);
  int k = 0, direction = -1;
  for (const ParameterField& f : fields) {
    auto it = fixed.find(f.name);
    const bool moves = f.role == FieldRole::kPosition || f.role == FieldRole::kAxisPoint;
    if (it != fixed.end())
      for (int j = 0; j < f.size; ++j) values[k + j] = it->second[j] - (moves ? centroid[j] : 0.0);
    if (f.role == FieldRole::kDirection && it != fixed.end()) direction = k;
    k += f.size;
  }
  // A fixed plane offset moves with the centroid when its normal is fixed too.
  int offset = 0;
  if (direction >= 0 && FindFieldWithRole(fields, FieldRole::kPlaneOffset, &offset) &&
      !std::isnan(values[offset])) {
    const Eigen::Vector3d n(values[direction], values[direction + 1], values[direction + 2]);
    values[offset] -= n.dot(centroid);  // n . (x - centroid) = d - n . centroid
  }
  return values;
}

void ApplyFixed(const std::vector<double>& fixed_values, std::vector<double>* params) {
  for (size_t k = 0; k < fixed_values.size() && k < params->size(); ++k)
    if (!std::isnan(fixed_values[k])) (*params)[k] = fixed_values[k];
}

HypothesisSearchResult FindHypothesis(const RecentredCloud& cloud,
                                      const std::vector<Eigen::Vector3d>& normals, double tau,
                                      const PrimitiveFitOptions& options,
                                      const std::vector<double>& fixed_values, std::mt19937& rng) {
  HypothesisSearchResult result;
  const NodeType kind = options.kind;
  const std::vector<Eigen::Vector3d>& pts = cloud.points;
  const size_t n = pts.size();
  // The scoring subsample (drawn first: the random sequence of a seed stays as it was).
  std::vector<size_t> sub(n);
  std::iota(sub.begin(), sub.end(), 0);
  if (n > static_cast<size_t>(options.score_subsample)) {
    PartialShuffle(&sub, options.score_subsample, rng);
    sub.resize(options.score_subsample);
  }
  if (!options.initial.empty()) {  // refinement from given parameters (e.g. the detector's)
    result.parameters = options.initial;
    TranslatePrimitive(kind, -cloud.centroid, &result.parameters);
    ApplyFixed(fixed_values, &result.parameters);
    return result;
  }
  if (normals.empty()) {
    const PointHypothesisSearch search = BestPointHypothesis(
        kind, pts, tau, options.hypotheses, rng,
        [&fixed_values](std::vector<double>* p) { ApplyFixed(fixed_values, p); });
    result.parameters = search.parameters;
    result.tried = search.tried;
    if (result.parameters.empty())
      result.message = "no valid hypothesis from " + std::to_string(search.tried) + " subsets of " +
                       std::to_string(PointSampleSize(kind, static_cast<int>(n))) +
                       " points (degenerate data for a " + NodeTypeName(kind) + "?)";
    return result;
  }
  const FittablePrimitive& entry = *FindFittablePrimitive(kind);
  result.parameters = VisitFittablePrimitive(kind, [&](auto e) {
    return RansacHypothesis<decltype(e)>(entry, pts, normals, sub, tau, options, fixed_values, rng);
  });
  result.tried = options.hypotheses;
  if (result.parameters.empty())
    result.message = "no valid hypothesis from " + std::to_string(options.hypotheses) +
                     " minimal samples (degenerate data for a " + NodeTypeName(kind) + "?)";
  return result;
}

std::vector<int> Classify(NodeType kind, const std::vector<double>& params,
                          const std::vector<Eigen::Vector3d>& points,
                          const std::vector<Eigen::Vector3d>& normals, const std::vector<int>& pool,
                          double limit, double normal_cos) {
  const Eigen::Vector3d no_normal = Eigen::Vector3d::UnitX();
  const double min_cos = normals.empty() ? 0.0 : normal_cos;
  return VisitFittablePrimitive(kind, [&](auto e) {
    std::vector<int> in;
    in.reserve(pool.size());
    const PrimitiveDistance<decltype(e)> f(params.data());
    for (int i : pool)
      if (Supports(f, points[i], normals.empty() ? no_normal : normals[i], limit, min_cos))
        in.push_back(i);
    return in;
  });
}

void SolveRound(NodeType kind, const std::vector<Eigen::Vector3d>& points,
                const std::vector<int>& inliers,
                const std::map<std::string, std::vector<double>>& fixed, int num_threads,
                ceres::Context* context, std::vector<double>* params, RefinementRound* round) {
  // The costs read the points as a flat xyz array (Vector3d is three packed doubles).
  static_assert(sizeof(Eigen::Vector3d) == 3 * sizeof(double),
                "Vector3d must be three packed doubles");
  const double* xyz = points[0].data();
  const std::vector<ParameterField>& fields = ParameterFieldsOf(kind);
  std::vector<int> block_sizes;
  round->blocks.clear();
  int k = 0;
  for (const ParameterField& f : fields) {
    round->blocks.emplace_back(params->begin() + k, params->begin() + k + f.size);
    block_sizes.push_back(f.size);
    k += f.size;
  }
  ceres::Problem::Options problem_options;
  problem_options.context = context;
  round->problem = std::make_unique<ceres::Problem>(problem_options);
  ceres::Problem* problem = round->problem.get();
  std::vector<double*> block_ptrs;
  for (auto& b : round->blocks) block_ptrs.push_back(b.data());
  // One compressed block (P + 1 residuals standing for a chunk of points, with the same
  // normal equations) per chunk: the chunks are evaluated in parallel.
  VisitFittablePrimitive(kind, [&](auto e) {
    using E = decltype(e);
    for (size_t s = 0; s < inliers.size(); s += kChunk) {
      std::vector<int> chunk(inliers.begin() + s,
                             inliers.begin() + std::min(inliers.size(), s + kChunk));
      problem->AddResidualBlock(new CompressedDistanceCost<E>(xyz, std::move(chunk), block_sizes),
                                nullptr, block_ptrs);
    }
    return 0;
  });
  for (size_t b = 0; b < fields.size(); ++b) {
    if (fixed.count(fields[b].name)) {
      problem->SetParameterBlockConstant(block_ptrs[b]);
      continue;
    }
    switch (fields[b].role) {
      case FieldRole::kDirection:
        problem->SetManifold(block_ptrs[b], new ceres::SphereManifold<3>());
        break;
      case FieldRole::kPositiveLength:
        for (int j = 0; j < fields[b].size; ++j)
          problem->SetParameterLowerBound(block_ptrs[b], j, 1e-12);
        break;
      case FieldRole::kAngle:
        problem->SetParameterLowerBound(block_ptrs[b], 0, 1e-6);
        problem->SetParameterUpperBound(block_ptrs[b], 0, M_PI / 2 - 1e-6);
        break;
      case FieldRole::kPlain:
      case FieldRole::kPosition:
      case FieldRole::kAxisPoint:
      case FieldRole::kPlaneOffset:
      case FieldRole::kRotation:
        break;
    }
  }
  ceres::Solver::Options solver_options;
  solver_options.linear_solver_type = ceres::DENSE_NORMAL_CHOLESKY;
  solver_options.num_threads = num_threads;
  solver_options.max_num_iterations = 50;
  // Stop once a step would lower the cost by less than kStepSd^2 / N of itself. Near the
  // optimum a Gauss-Newton step delta lowers the cost 0.5 sum r^2 ~ 0.5 N sigma^2 by
  // 0.5 delta^T J^T J delta = 0.5 sigma^2 m^2, m the Mahalanobis length of delta in units of the
  // parameters' standard deviation; so the step left untaken is at most ~kStepSd of a standard
  // deviation (never looser than Ceres' default 1e-6).
  solver_options.function_tolerance =
      std::min(1e-6, kStepSd * kStepSd / static_cast<double>(inliers.size()));
  solver_options.parameter_tolerance = 1e-12;
  // Bounds (radii, the cone angle) are enforced by projecting each step onto them; Ceres'
  // projected line search on top costs a second Jacobian evaluation per iteration.
  solver_options.max_num_line_search_step_size_iterations = 0;
  ceres::Solve(solver_options, problem, &round->summary);
  k = 0;
  for (auto& b : round->blocks) {
    std::copy(b.begin(), b.end(), params->begin() + k);
    k += static_cast<int>(b.size());
  }
}

Reclassification Reclassify(NodeType kind, const std::vector<double>& params,
                            const std::vector<Eigen::Vector3d>& points,
                            const std::vector<Eigen::Vector3d>& normals,
                            const std::vector<int>& pool, const std::vector<int>& inliers,
                            const PrimitiveFitOptions& options) {
  Reclassification r;
  std::vector<double> abs_r;
  abs_r.reserve(inliers.size());
  VisitFittablePrimitive(kind, [&](auto e) {
    const PrimitiveDistance<decltype(e)> f(params.data());
    for (int i : inliers) abs_r.push_back(std::abs(f(points[i].data(), nullptr, nullptr)));
    return 0;
  });
  r.sigma = 1.4826 * Median(abs_r);
  r.band = std::max(options.band_sigmas * r.sigma, 1e-12);
  if (options.threshold > 0) {
    r.band = options.threshold;  // a fixed inlier distance: no re-estimation
  } else if (normals.empty()) {
    // Few points: with N - k redundant residuals the median misjudges the scale (N = k + 1:
    // one residual direction, most |f| near 0); the residual standard error sqrt(RSS/(N - k))
    // bounds the band from below.
    double rss = 0.0;
    for (double v : abs_r) rss += v * v;
    const double dof = std::max(1.0, static_cast<double>(abs_r.size()) - FreeParameterCount(kind));
    r.band = std::max(r.band, options.band_sigmas * std::sqrt(rss / dof));
  }
  r.inliers = Classify(kind, params, points, normals, pool, r.band, options.normal_cos);
  // Stable: the inlier set changed by at most stable_fraction (points flickering at the band's
  // edge move the solution by far less than its standard deviation).
  std::vector<int> changed;
  std::set_symmetric_difference(r.inliers.begin(), r.inliers.end(), inliers.begin(), inliers.end(),
                                std::back_inserter(changed));
  r.stable = changed.size() <= options.stable_fraction * inliers.size();
  return r;
}

InlierFigures Figures(NodeType kind, const std::vector<double>& params,
                      const std::vector<Eigen::Vector3d>& points,
                      const std::vector<Eigen::Vector3d>& normals,
                      const std::vector<int>& inliers) {
  InlierFigures fig;
  double angle_sum = 0.0;
  VisitFittablePrimitive(kind, [&](auto e) {
    const PrimitiveDistance<decltype(e)> f(params.data());
    for (int i : inliers) {
      double g[3];
      const double r = f(points[i].data(), nullptr, g);
      fig.rss += r * r;
      fig.max_abs = std::max(fig.max_abs, std::abs(r));
      if (!normals.empty())
        angle_sum += AcosUnit(std::min(1.0, NormalCos(g, normals[i]))) * 180.0 / M_PI;
    }
    return 0;
  });
  const double n = static_cast<double>(inliers.size());
  fig.rms = inliers.empty() ? 0.0 : std::sqrt(fig.rss / n);
  fig.mean_normal_angle_deg = normals.empty() || inliers.empty() ? -1.0 : angle_sum / n;
  return fig;
}

std::vector<double> StandardDeviations(NodeType kind, RefinementRound* round,
                                       const std::map<std::string, std::vector<double>>& fixed,
                                       double rss, size_t inliers, int num_threads) {
  ceres::Problem* problem = round->problem.get();
  std::vector<double> sd(NumParametersOf(kind), 0.0);
  if (!problem) return sd;
  ceres::Covariance::Options cov_options;
  cov_options.algorithm_type = ceres::DENSE_SVD;
  cov_options.null_space_rank = -1;  // the cylinder's point slides along its axis: pseudo-inverse
  cov_options.num_threads = num_threads;
  ceres::Covariance covariance(cov_options);
  std::vector<std::pair<const double*, const double*>> pairs;
  for (auto& b : round->blocks)
    if (!problem->IsParameterBlockConstant(b.data())) pairs.emplace_back(b.data(), b.data());
  if (!covariance.Compute(pairs, problem)) return sd;
  // Degrees of freedom: a direction has 2 (its length is not a parameter of the surface).
  int dof = 0;
  for (const ParameterField& f : ParameterFieldsOf(kind))
    if (!fixed.count(f.name)) dof += f.role == FieldRole::kDirection ? 2 : f.size;
  const double s2 = rss / std::max<double>(1.0, static_cast<double>(inliers) - dof);
  int k = 0;
  for (auto& b : round->blocks) {
    if (!problem->IsParameterBlockConstant(b.data())) {
      Eigen::MatrixXd c(b.size(), b.size());
      covariance.GetCovarianceBlock(b.data(), b.data(), c.data());
      for (size_t j = 0; j < b.size(); ++j) sd[k + j] = std::sqrt(std::max(0.0, c(j, j) * s2));
    }
    k += static_cast<int>(b.size());
  }
  return sd;
}

}  // namespace implicitfit
