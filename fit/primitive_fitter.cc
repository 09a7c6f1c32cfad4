#include "fit/primitive_fitter.h"

#include <ceres/ceres.h>
#include <ceres/context.h>
#include <ceres/covariance.h>
#include <ceres/sphere_manifold.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iterator>
#include <numeric>
#include <random>
#include <thread>

#include "fit/compressed_distance_cost.h"
#include "fit/estimator_stage.h"
#include "fit/minimal_samples.h"
#include "fit/point_hypotheses.h"
#include "fit/primitive_jacobians.h"
#include "fit/primitive_tangent.h"
#include "fit/thread_count.h"
#include "model/median.h"

namespace implicitfit {
namespace {

// Points per residual block (fit/compressed_distance_cost.h).
constexpr size_t kChunk = 4096;
// Solver stops when the next step would move the parameters by less than this many standard
// deviations (see the function tolerance below).
constexpr double kStepSd = 0.05;

bool IsPositionField(const std::string& f) { return f == "center" || f == "point" || f == "apex"; }
bool IsDirectionField(const std::string& f) { return f == "axis" || f == "normal"; }
bool IsRadiusField(const std::string& f) {
  return f == "radius" || f == "major_radius" || f == "minor_radius";
}

// Moves the parameters of a primitive by -shift (recentring) or +shift.
void Translate(NodeType kind, std::vector<double>* p, const Eigen::Vector3d& shift) {
  int k = 0;
  for (const ParameterField& f : ParameterFieldsOf(kind)) {
    if (IsPositionField(f.name))
      for (int j = 0; j < 3; ++j) (*p)[k + j] += shift[j];
    k += f.size;
  }
  if (kind == NodeType::kPlane) {
    const Eigen::Vector3d n((*p)[0], (*p)[1], (*p)[2]);
    (*p)[3] += n.dot(shift) / n.norm();
  }
}

// Normalises directions and puts the primitive in a canonical form.
void Canonicalise(NodeType kind, std::vector<double>* p, const Eigen::Vector3d& centroid) {
  int k = 0;
  for (const ParameterField& f : ParameterFieldsOf(kind)) {
    if (IsDirectionField(f.name)) {
      Eigen::Map<Eigen::Vector3d> v(p->data() + k);
      const double n = v.norm();
      v /= n;
      if (kind == NodeType::kPlane) (*p)[3] /= n;
    }
    k += f.size;
  }
  if (kind == NodeType::kCylinder) {  // point on the axis closest to the centroid
    Eigen::Map<Eigen::Vector3d> q(p->data()), a(p->data() + 3);
    q += a * a.dot(centroid - q);
  }
}

// Closed-form f and grad f (fit/primitive_jacobians.h) for the inlier tests.
template <typename E>
struct Kind {
  static_assert(PrimitiveDistance<E>::kAvailable,
                "the primitive fitter needs closed-form derivatives");
  // True when |f(x)| < limit and |cos(grad f(x), n)| >= min_cos.
  static bool Supports(const PrimitiveDistance<E>& f, const Eigen::Vector3d& x,
                       const Eigen::Vector3d& n, double limit, double min_cos) {
    double g[3];
    if (!(std::abs(f(x.data(), nullptr, g)) < limit)) return false;
    return NormalCos(g, n) >= min_cos;
  }
  // |cos(g, n)|, 0 for a zero gradient.
  static double NormalCos(const double* g, const Eigen::Vector3d& n) {
    const double gn = std::sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]);
    return gn > 0 ? std::abs(g[0] * n[0] + g[1] * n[1] + g[2] * n[2]) / gn : 0.0;
  }
};

struct Hypothesizer {
  NodeType kind;
  const std::vector<Eigen::Vector3d>& x;
  const std::vector<Eigen::Vector3d>& n;
  std::mt19937& rng;

  bool Draw(std::vector<double>* params) {
    std::uniform_int_distribution<size_t> pick(0, x.size() - 1);
    switch (kind) {
      case NodeType::kPlane: {
        const size_t i = pick(rng);
        return PlaneFromSample(x[i], n[i], params);
      }
      case NodeType::kSphere:
      case NodeType::kCylinder: {
        const size_t i = pick(rng), j = pick(rng);
        if (i == j) return false;
        const Vec3 p[2] = {x[i], x[j]}, m[2] = {n[i], n[j]};
        return kind == NodeType::kSphere ? SphereFromSample(p, m, params)
                                         : CylinderFromSample(p, m, params);
      }
      case NodeType::kCone: {
        const size_t i = pick(rng), j = pick(rng), k = pick(rng);
        if (i == j || j == k || i == k) return false;
        const Vec3 p[3] = {x[i], x[j], x[k]}, m[3] = {n[i], n[j], n[k]};
        return ConeFromSample(p, m, params);
      }
      case NodeType::kTorus: {
        std::vector<Vec3> p, m;
        for (int s = 0; s < 7; ++s) {
          const size_t i = pick(rng);
          p.push_back(x[i]);
          m.push_back(n[i]);
        }
        return TorusFromSample(p, m, params);
      }
      case NodeType::kEllipsoid:
      case NodeType::kQuadric:
      case NodeType::kBernsteinPatch:
      case NodeType::kUnion:
      case NodeType::kIntersection:
      case NodeType::kDifference:
      case NodeType::kBox:
      case NodeType::kComplement:
      case NodeType::kMorph:
      case NodeType::kParaboloid:
      case NodeType::kBlobs:
      case NodeType::kSkeletonOffset:
      case NodeType::kPartition:
      case NodeType::kBernsteinMesh:
      case NodeType::kPartitionSequence:
      case NodeType::kColemanFeatures:
        return false;  // no minimal-sample hypothesis (PrimitiveFitOptions::IsValid refuses them)
    }
    return false;
  }
};

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

template <typename E>
PrimitiveFitResult Fit(const std::vector<Eigen::Vector3d>& input_points,
                       const std::vector<Eigen::Vector3d>& input_normals,
                       const PrimitiveFitOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  PrimitiveFitResult result;
  const NodeType kind = options.kind;
  const size_t N = input_points.size();
  const bool has_normals = !input_normals.empty();

  // Recentred copy (precision with large coordinates), as a flat xyz array for the costs.
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  for (const auto& p : input_points) centroid += p;
  centroid /= static_cast<double>(N);
  std::vector<Eigen::Vector3d> pts(N);
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(INFINITY), hi = -lo;
  for (size_t i = 0; i < N; ++i) {
    pts[i] = input_points[i] - centroid;
    lo = lo.cwiseMin(pts[i]);
    hi = hi.cwiseMax(pts[i]);
  }
  // The costs read pts as a flat xyz array (Vector3d is three packed doubles), no second copy.
  static_assert(sizeof(Eigen::Vector3d) == 3 * sizeof(double),
                "Vector3d must be three packed doubles");
  const double* xyz = pts[0].data();
  const double tau = options.threshold > 0 ? options.threshold : 0.01 * (hi - lo).norm();

  // Without normals: hypotheses from points alone (fit/point_hypotheses.h).
  const Eigen::Vector3d no_normal = Eigen::Vector3d::UnitX();
  const double normal_cos = has_normals ? options.normal_cos : 0.0;
  result.points_only = !has_normals;
  if (!has_normals) {
    result.message = PointSetDegeneracy(kind, pts);
    if (kind == NodeType::kTorus && result.message.empty())
      result.message = "a torus needs normals: it is not hypothesised from points alone";
    if (!result.message.empty()) return result;
  }

  // Fixed fields, in the recentred frame.
  std::vector<double> fixed_values(E::kNumParameters, NAN);
  {
    int k = 0;
    for (const ParameterField& f : ParameterFieldsOf(kind)) {
      auto it = options.fixed.find(f.name);
      if (it != options.fixed.end())
        for (int j = 0; j < f.size; ++j)
          fixed_values[k + j] = it->second[j] - (IsPositionField(f.name) ? centroid[j] : 0.0);
      k += f.size;
    }
    if (kind == NodeType::kPlane && options.fixed.count("offset") &&
        options.fixed.count("normal")) {
      const auto& nn = options.fixed.at("normal");
      const Eigen::Vector3d nv(nn[0], nn[1], nn[2]);
      fixed_values[3] = options.fixed.at("offset")[0] - nv.dot(centroid) / nv.norm();
    }
  }
  auto apply_fixed = [&](std::vector<double>* p) {
    for (int k = 0; k < E::kNumParameters; ++k)
      if (!std::isnan(fixed_values[k])) (*p)[k] = fixed_values[k];
  };

  // 1. Hypotheses scored on a subsample.
  std::mt19937 rng(options.seed);
  std::vector<size_t> sub(N);
  std::iota(sub.begin(), sub.end(), 0);
  if (N > static_cast<size_t>(options.score_subsample)) {
    PartialShuffle(&sub, options.score_subsample, rng);
    sub.resize(options.score_subsample);
  }
  Hypothesizer draw{kind, pts, input_normals, rng};
  std::vector<double> best;
  int best_score = -1;
  std::vector<double> h;
  // Adaptive RANSAC stopping: after t draws with best inlier ratio w, a sample of m points
  // free of outliers was drawn with probability 1 - (1 - w^m)^t; stop once that reaches
  // options.confidence (and after at least options.min_hypotheses).
  const int m = kind == NodeType::kPlane   ? 1
                : kind == NodeType::kCone  ? 3
                : kind == NodeType::kTorus ? 7
                                           : 2;
  int needed = options.hypotheses;
  if (!options.initial.empty()) {  // refinement from given parameters (e.g. the detector's)
    best = options.initial;
    Translate(kind, &best, -centroid);
    apply_fixed(&best);
    needed = 0;
  }
  for (int t = 0; has_normals && t < needed; ++t) {
    if (!draw.Draw(&h)) continue;
    apply_fixed(&h);
    const PrimitiveDistance<E> hf(h.data());
    int score = 0;
    for (size_t i : sub)
      score += Kind<E>::Supports(hf, pts[i], input_normals[i], tau, options.normal_cos);
    if (score > best_score) {
      best_score = score;
      best = h;
      const double w = std::min(0.999, static_cast<double>(score) / sub.size());
      const double k = std::log(1.0 - options.confidence) / std::log(1.0 - std::pow(w, m));
      if (std::isfinite(k))
        needed =
            std::clamp(static_cast<int>(std::ceil(k)), options.min_hypotheses, options.hypotheses);
    }
  }
  if (!has_normals && options.initial.empty()) {
    const PointHypothesisSearch search =
        BestPointHypothesis(kind, pts, tau, options.hypotheses, rng, apply_fixed);
    best = search.parameters;
    if (best.empty()) {
      result.message = "no valid hypothesis from " + std::to_string(search.tried) + " subsets of " +
                       std::to_string(FreeParameterCount(kind)) +
                       " points (degenerate data for a " + NodeTypeName(kind) + "?)";
      return result;
    }
  }
  if (best.empty()) {
    result.message = "no valid hypothesis from " + std::to_string(options.hypotheses) +
                     " minimal samples (degenerate data for a " + NodeTypeName(kind) + "?)";
    return result;
  }

  // 2. Robust refinement.
  std::vector<double> params = best;
  std::vector<int> inliers;
  double band = tau;
  // Coarse rounds run on a random working subset (the inlier set and scale settle there at a
  // fraction of the cost); the final rounds use every point.
  std::vector<int> working(N);
  std::iota(working.begin(), working.end(), 0);
  if (N > static_cast<size_t>(options.working_subsample)) {
    PartialShuffle(&working, options.working_subsample, rng);
    working.resize(options.working_subsample);
    std::sort(working.begin(), working.end());
  }
  std::vector<int> all(N);
  std::iota(all.begin(), all.end(), 0);
  const std::vector<int>* pool = &working;
  auto classify = [&](const std::vector<double>& p, double limit) {
    std::vector<int> in;
    in.reserve(pool->size());
    const PrimitiveDistance<E> f(p.data());
    for (int i : *pool)
      if (Kind<E>::Supports(f, pts[i], has_normals ? input_normals[i] : no_normal, limit,
                            normal_cos))
        in.push_back(i);
    return in;
  };
  inliers = classify(params, band);
  const std::vector<ParameterField>& fields = ParameterFieldsOf(kind);
  std::vector<int> block_sizes;
  for (const ParameterField& f : fields) block_sizes.push_back(f.size);
  ceres::Solver::Summary summary;
  // One Ceres context (its thread pool) for every round's problem, instead of one per problem.
  std::unique_ptr<ceres::Context> context(ceres::Context::Create());
  std::unique_ptr<ceres::Problem> problem;
  std::vector<std::vector<double>> blocks;
  const int threads = ThreadCountOrDefault(options.num_threads);
  bool final_stage = pool->size() == N;
  for (int round = 0; round < options.max_rounds + 3; ++round) {
    const size_t floor = has_normals ? options.min_inliers : FreeParameterCount(kind) + 1;
    const size_t min_needed = std::max<size_t>(floor, options.min_inlier_fraction * pool->size());
    if (inliers.size() < min_needed) {
      result.message = "too few inliers: " + std::to_string(inliers.size()) + " of " +
                       std::to_string(N) + " points (need " + std::to_string(min_needed) + ")";
      result.parameters = params;
      Translate(kind, &result.parameters, centroid);
      return result;
    }
    // Least squares on the current inliers.
    blocks.clear();
    int k = 0;
    for (const ParameterField& f : fields) {
      blocks.emplace_back(params.begin() + k, params.begin() + k + f.size);
      k += f.size;
    }
    ceres::Problem::Options problem_options;
    problem_options.context = context.get();
    problem = std::make_unique<ceres::Problem>(problem_options);
    std::vector<double*> block_ptrs;
    for (auto& b : blocks) block_ptrs.push_back(b.data());
    // One compressed block (P + 1 residuals standing for a chunk of points, with the same
    // normal equations) per chunk: the chunks are evaluated in parallel.
    for (size_t s = 0; s < inliers.size(); s += kChunk) {
      std::vector<int> chunk(inliers.begin() + s,
                             inliers.begin() + std::min(inliers.size(), s + kChunk));
      problem->AddResidualBlock(new CompressedDistanceCost<E>(xyz, std::move(chunk), block_sizes),
                                nullptr, block_ptrs);
    }
    for (size_t b = 0; b < fields.size(); ++b) {
      const std::string name = fields[b].name;
      if (options.fixed.count(name)) {
        problem->SetParameterBlockConstant(block_ptrs[b]);
        continue;
      }
      if (IsDirectionField(name))
        problem->SetManifold(block_ptrs[b], new ceres::SphereManifold<3>());
      if (IsRadiusField(name)) problem->SetParameterLowerBound(block_ptrs[b], 0, 1e-12);
      if (name == "half_angle") {
        problem->SetParameterLowerBound(block_ptrs[b], 0, 1e-6);
        problem->SetParameterUpperBound(block_ptrs[b], 0, M_PI / 2 - 1e-6);
      }
    }
    ceres::Solver::Options solver_options;
    solver_options.linear_solver_type = ceres::DENSE_NORMAL_CHOLESKY;
    solver_options.num_threads = threads;
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
    ceres::Solve(solver_options, problem.get(), &summary);
    result.iterations += static_cast<int>(summary.iterations.size());
    result.rounds = round + 1;
    k = 0;
    for (auto& b : blocks) {
      std::copy(b.begin(), b.end(), params.begin() + k);
      k += static_cast<int>(b.size());
    }
    // Re-estimate the scale from the inliers, re-classify.
    std::vector<double> abs_r;
    abs_r.reserve(inliers.size());
    const PrimitiveDistance<E> f(params.data());
    for (int i : inliers) abs_r.push_back(std::abs(f(pts[i].data(), nullptr, nullptr)));
    result.sigma = 1.4826 * Median(abs_r);
    band = std::max(options.band_sigmas * result.sigma, 1e-12);
    if (!has_normals) {
      // Few points: with N - k redundant residuals the median misjudges the scale (N = k + 1:
      // one residual direction, most |f| near 0); the residual standard error sqrt(RSS/(N - k))
      // bounds the band from below.
      double rss = 0.0;
      for (double v : abs_r) rss += v * v;
      const double dof =
          std::max(1.0, static_cast<double>(abs_r.size()) - FreeParameterCount(kind));
      band = std::max(band, options.band_sigmas * std::sqrt(rss / dof));
    }
    std::vector<int> next = classify(params, band);
    // Stable: the inlier set changed by at most 0.2% (points flickering at the band's edge move
    // the solution by far less than its standard deviation).
    std::vector<int> changed;
    std::set_symmetric_difference(next.begin(), next.end(), inliers.begin(), inliers.end(),
                                  std::back_inserter(changed));
    const bool stable = changed.size() <= options.stable_fraction * inliers.size();
    inliers = std::move(next);
    if (stable || round + 1 == options.max_rounds) {
      if (final_stage) break;
      final_stage = true;  // switch to every point
      pool = &all;
      inliers = classify(params, band);
    }
  }

  // 3. Figures and uncertainties.
  result.inliers = inliers;
  double ss = 0.0, angle_sum = 0.0;
  const PrimitiveDistance<E> pf(params.data());
  for (int i : inliers) {
    double g[3];
    const double r = pf(pts[i].data(), nullptr, g);
    ss += r * r;
    result.max_abs = std::max(result.max_abs, std::abs(r));
    if (has_normals)
      angle_sum += AcosUnit(std::min(1.0, Kind<E>::NormalCos(g, input_normals[i]))) * 180.0 / M_PI;
  }
  result.rms = std::sqrt(ss / inliers.size());
  result.mean_normal_angle_deg = has_normals ? angle_sum / inliers.size() : -1.0;

  if (options.compute_covariance && problem) {
    ceres::Covariance::Options cov_options;
    cov_options.algorithm_type = ceres::DENSE_SVD;
    cov_options.null_space_rank = -1;  // the cylinder's point slides along its axis: pseudo-inverse
    cov_options.num_threads = threads;
    ceres::Covariance covariance(cov_options);
    std::vector<std::pair<const double*, const double*>> pairs;
    std::vector<const double*> free_blocks;
    for (auto& b : blocks)
      if (!problem->IsParameterBlockConstant(b.data())) {
        pairs.emplace_back(b.data(), b.data());
        free_blocks.push_back(b.data());
      }
    result.standard_deviations.assign(E::kNumParameters, 0.0);
    if (covariance.Compute(pairs, problem.get())) {
      int dof = 0;
      for (const ParameterField& f : fields)
        if (!options.fixed.count(f.name)) dof += IsDirectionField(f.name) ? 2 : f.size;
      const double s2 = ss / std::max<double>(1.0, static_cast<double>(inliers.size()) - dof);
      int k = 0;
      for (auto& b : blocks) {
        if (!problem->IsParameterBlockConstant(b.data())) {
          Eigen::MatrixXd c(b.size(), b.size());
          covariance.GetCovarianceBlock(b.data(), b.data(), c.data());
          for (size_t j = 0; j < b.size(); ++j)
            result.standard_deviations[k + j] = std::sqrt(std::max(0.0, c(j, j) * s2));
        }
        k += static_cast<int>(b.size());
      }
    }
  }

  Canonicalise(kind, &params, Eigen::Vector3d::Zero());
  Translate(kind, &params, centroid);
  result.parameters = params;
  const bool converged = summary.termination_type == ceres::CONVERGENCE;
  result.success = converged && summary.IsSolutionUsable();
  result.message = converged ? "converged" : "solver did not converge: " + summary.message;
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
  if (!(k == NodeType::kPlane || k == NodeType::kSphere || k == NodeType::kCylinder ||
        k == NodeType::kCone || k == NodeType::kTorus))
    return fail(std::string("cannot fit a ") + NodeTypeName(k) + " with the primitive fitter");
  if (hypotheses < 1 || min_hypotheses < 1)
    return fail("hypotheses and min_hypotheses must be >= 1");
  if (!(confidence > 0 && confidence < 1)) return fail("confidence must be in (0, 1)");
  if (!initial.empty() && static_cast<int>(initial.size()) != NumParametersOf(k))
    return fail("initial parameters: " + std::to_string(initial.size()) + " values, a " +
                NodeTypeName(k) + " has " + std::to_string(NumParametersOf(k)));
  if (score_subsample < 10 || working_subsample < 10)
    return fail("subsamples must hold >= 10 points");
  if (!(normal_cos >= 0 && normal_cos <= 1)) return fail("normal_cos must be in [0, 1]");
  if (!(band_sigmas > 0)) return fail("band_sigmas must be > 0");
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
  for (NodeType k : {NodeType::kPlane, NodeType::kSphere, NodeType::kCylinder, NodeType::kCone,
                     NodeType::kTorus})
    if (name == NodeTypeName(k)) {
      *kind = k;
      return true;
    }
  return false;
}

PrimitiveFitResult FitPrimitive(const std::vector<Eigen::Vector3d>& points,
                                const std::vector<Eigen::Vector3d>& normals,
                                const PrimitiveFitOptions& options) {
  PrimitiveFitResult result;
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
  switch (options.kind) {
    case NodeType::kPlane:
      result = Fit<PlaneEvaluator>(points, normals, options);
      break;
    case NodeType::kSphere:
      result = Fit<SphereEvaluator>(points, normals, options);
      break;
    case NodeType::kCylinder:
      result = Fit<CylinderEvaluator>(points, normals, options);
      break;
    case NodeType::kCone:
      result = Fit<ConeEvaluator>(points, normals, options);
      break;
    case NodeType::kTorus:
      result = Fit<TorusEvaluator>(points, normals, options);
      break;
    case NodeType::kEllipsoid:
    case NodeType::kQuadric:
    case NodeType::kBernsteinPatch:
    case NodeType::kUnion:
    case NodeType::kIntersection:
    case NodeType::kDifference:
    case NodeType::kBox:
    case NodeType::kComplement:
    case NodeType::kMorph:
    case NodeType::kParaboloid:
    case NodeType::kBlobs:
    case NodeType::kSkeletonOffset:
    case NodeType::kPartition:
    case NodeType::kBernsteinMesh:
    case NodeType::kPartitionSequence:
    case NodeType::kColemanFeatures:
      result.message = std::string("unsupported kind: ") + NodeTypeName(options.kind);
      return result;
  }
  FinishWithEstimator(points, options, &result);
  return result;
}

}  // namespace implicitfit
