#include "fit/splines/bspline_surface_fitter.h"

#include <ceres/ceres.h>

#include <Eigen/Geometry>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>

#include "fit/common/thread_count.h"
#include "fit/splines/parameter_frame.h"
#include "model/splines/bspline_evaluation.h"
#include "model/splines/closest_point.h"

namespace implicitfit {
namespace {

using Vec = Eigen::Vector3d;

SplineStructure Structure(const SurfaceFitOptions& o) {
  SplineStructure s;
  s.degree[0] = s.degree[1] = o.degree;
  s.count[0] = o.count_u;
  s.count[1] = o.count_v;
  s.knots[0] = ClampedUniformKnots(o.degree, o.count_u, 0.0, 1.0);
  s.knots[1] = ClampedUniformKnots(o.degree, o.count_v, 0.0, 1.0);
  return s;
}

// The normal equations of the data and smoothing terms in banded form: entry (a, b) of the
// n_c x n_c matrix with |i_a - i_b| <= p and |j_a - j_b| <= q is at band[a][offset(b - a)].
class NormalEquations {
 public:
  NormalEquations(int nu, int nv, int p, int q)
      : nu_(nu), nv_(nv), p_(p), q_(q), width_((2 * p + 1) * (2 * q + 1)),
        band_(static_cast<size_t>(nu) * nv * width_, 0.0), rhs_(nu * nv, 3) {
    rhs_.setZero();
  }
  void Add(int a, int b, double value) {
    const int di = b / nv_ - a / nv_, dj = b % nv_ - a % nv_;
    band_[static_cast<size_t>(a) * width_ + (di + p_) * (2 * q_ + 1) + (dj + q_)] += value;
  }
  void AddRhs(int a, const Vec& value) { rhs_.row(a) += value.transpose(); }
  // A row r = sum_t w_t P_{index_t} - target (weights w) into H and the right-hand side.
  void AddRow(const int* index, const double* w, int terms, const Vec& target) {
    for (int s = 0; s < terms; ++s) {
      for (int t = 0; t < terms; ++t) Add(index[s], index[t], w[s] * w[t]);
      AddRhs(index[s], w[s] * target);
    }
  }
  // Solves (H + ridge I) P = rhs; false when the factorisation fails.
  bool Solve(std::vector<double>* points) const {
    const int n = nu_ * nv_;
    std::vector<Eigen::Triplet<double>> entries;
    double trace = 0.0;
    for (int a = 0; a < n; ++a) trace += band_[static_cast<size_t>(a) * width_ + width_ / 2];
    const double ridge = 1e-12 * trace / n + 1e-300;
    for (int a = 0; a < n; ++a)
      for (int o = 0; o < width_; ++o) {
        const double v = band_[static_cast<size_t>(a) * width_ + o];
        if (v == 0.0 && o != width_ / 2) continue;
        const int di = o / (2 * q_ + 1) - p_, dj = o % (2 * q_ + 1) - q_;
        const int b = a + di * nv_ + dj;
        entries.emplace_back(a, b, v + (o == width_ / 2 ? ridge : 0.0));
      }
    Eigen::SparseMatrix<double> h(n, n);
    h.setFromTriplets(entries.begin(), entries.end());
    Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt(h);
    if (ldlt.info() != Eigen::Success) return false;
    const Eigen::MatrixXd x = ldlt.solve(rhs_);
    if (!x.allFinite()) return false;
    points->resize(3 * static_cast<size_t>(n));
    for (int a = 0; a < n; ++a)
      for (int k = 0; k < 3; ++k) (*points)[3 * a + k] = x(a, k);
    return true;
  }

 private:
  int nu_, nv_, p_, q_, width_;
  std::vector<double> band_;
  Eigen::MatrixXd rhs_;
};

// The second differences along u, along v and the twist, weights 1, 2, 1 (the thin-plate
// energy's), each a row of three or four control points with target 0.
template <typename Visit>
void SmoothingRows(int nu, int nv, const Visit& visit) {
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j) {
      if (i + 2 < nu) {
        const int idx[3] = {i * nv + j, (i + 1) * nv + j, (i + 2) * nv + j};
        const double w[3] = {1.0, -2.0, 1.0};
        visit(idx, w, 3);
      }
      if (j + 2 < nv) {
        const int idx[3] = {i * nv + j, i * nv + j + 1, i * nv + j + 2};
        const double w[3] = {1.0, -2.0, 1.0};
        visit(idx, w, 3);
      }
      if (i + 1 < nu && j + 1 < nv) {
        const int idx[4] = {i * nv + j, i * nv + j + 1, (i + 1) * nv + j, (i + 1) * nv + j + 1};
        const double s = std::sqrt(2.0);
        const double w[4] = {s, -s, -s, s};
        visit(idx, w, 4);
      }
    }
}

// Step 1's linear solve for fixed parameters.
bool LinearControlPoints(const SplineStructure& s, const std::vector<Vec>& points,
                         const std::vector<Eigen::Vector2d>& uv, double lambda,
                         std::vector<double>* control) {
  const int p = s.degree[0], q = s.degree[1], nu = s.count[0], nv = s.count[1];
  NormalEquations eq(nu, nv, p, q);
  int index[(kMaxSplineDegree + 1) * (kMaxSplineDegree + 1)];
  double w[(kMaxSplineDegree + 1) * (kMaxSplineDegree + 1)];
  for (size_t k = 0; k < points.size(); ++k) {
    const int su = FindSpan(p, nu, s.knots[0].data(), uv[k][0]);
    const int sv = FindSpan(q, nv, s.knots[1].data(), uv[k][1]);
    double bu[kMaxSplineDegree + 1], bv[kMaxSplineDegree + 1];
    BasisFunctions(su, uv[k][0], p, s.knots[0].data(), bu);
    BasisFunctions(sv, uv[k][1], q, s.knots[1].data(), bv);
    int t = 0;
    for (int a = 0; a <= p; ++a)
      for (int b = 0; b <= q; ++b) {
        index[t] = (su - p + a) * nv + (sv - q + b);
        w[t++] = bu[a] * bv[b];
      }
    eq.AddRow(index, w, t, points[k]);
  }
  const double root = std::sqrt(lambda);
  SmoothingRows(nu, nv, [&](const int* idx, const double* weights, int terms) {
    double scaled[4];
    for (int t = 0; t < terms; ++t) scaled[t] = root * weights[t];
    eq.AddRow(idx, scaled, terms, Vec::Zero());
  });
  return eq.Solve(control);
}

// Every point's foot: a local Newton from its current parameters, or (global) the robust
// search of model/splines/closest_point.h with the current parameters as an extra start.
double Project(const SplineStructure& s, const std::vector<double>& control,
               const std::vector<Vec>& points, bool global, int threads,
               std::vector<Eigen::Vector2d>* uv) {
  std::vector<double> d2(points.size());
  ParallelFor(points.size(), threads, [&](size_t begin, size_t end) {
    for (size_t k = begin; k < end; ++k) {
      const double start[2] = {(*uv)[k][0], (*uv)[k][1]};
      const SurfaceFoot foot =
          global ? ClosestSurfacePoint(s, control.data(), points[k].data(), start)
                 : SurfaceFootFrom(s, control.data(), points[k].data(), start[0], start[1]);
      (*uv)[k] = Eigen::Vector2d(foot.u, foot.v);
      d2[k] = foot.distance2;
    }
  });
  double sum = 0.0;
  for (double v : d2) sum += v;
  return std::sqrt(sum / std::max<size_t>(1, points.size()));
}

// x_k - S(u_k, v_k) with the span (su, sv) held fixed; blocks [uv (2), the (p+1)(q+1) control
// points of the span (3 each), u-major].
class SurfacePointCost final : public ceres::CostFunction {
 public:
  SurfacePointCost(const SplineStructure* s, const Vec& x, int su, int sv)
      : s_(s), x_(x), su_(su), sv_(sv) {
    set_num_residuals(3);
    mutable_parameter_block_sizes()->push_back(2);
    for (int t = 0; t < (s->degree[0] + 1) * (s->degree[1] + 1); ++t)
      mutable_parameter_block_sizes()->push_back(3);
  }
  bool Evaluate(double const* const* parameters, double* residuals,
                double** jacobians) const override {
    const int p = s_->degree[0], q = s_->degree[1];
    const double u = parameters[0][0], v = parameters[0][1];
    double du[2 * (kMaxSplineDegree + 1)], dv[2 * (kMaxSplineDegree + 1)];
    BasisDerivatives(su_, u, p, std::min(1, p), s_->knots[0].data(), du);
    BasisDerivatives(sv_, v, q, std::min(1, q), s_->knots[1].data(), dv);
    Vec S = Vec::Zero(), Su = Vec::Zero(), Sv = Vec::Zero();
    for (int a = 0; a <= p; ++a)
      for (int b = 0; b <= q; ++b) {
        const Eigen::Map<const Vec> P(parameters[1 + a * (q + 1) + b]);
        S += du[a] * dv[b] * P;
        Su += du[p + 1 + a] * dv[b] * P;
        Sv += du[a] * dv[q + 1 + b] * P;
      }
    for (int c = 0; c < 3; ++c) residuals[c] = S[c] - x_[c];
    if (!jacobians) return true;
    if (jacobians[0])
      for (int c = 0; c < 3; ++c) {
        jacobians[0][2 * c] = Su[c];
        jacobians[0][2 * c + 1] = Sv[c];
      }
    for (int a = 0; a <= p; ++a)
      for (int b = 0; b <= q; ++b) {
        double* j = jacobians[1 + a * (q + 1) + b];
        if (!j) continue;
        const double w = du[a] * dv[b];
        for (int r = 0; r < 3; ++r)
          for (int c = 0; c < 3; ++c) j[3 * r + c] = r == c ? w : 0.0;
      }
    return true;
  }

 private:
  const SplineStructure* s_;
  Vec x_;
  int su_, sv_;
};

// sqrt(lambda) sum_t w_t P_t (one smoothing row of SmoothingRows).
class SmoothingCost final : public ceres::CostFunction {
 public:
  SmoothingCost(const double* w, int terms, double root) : terms_(terms) {
    for (int t = 0; t < terms; ++t) w_[t] = root * w[t];
    set_num_residuals(3);
    for (int t = 0; t < terms; ++t) mutable_parameter_block_sizes()->push_back(3);
  }
  bool Evaluate(double const* const* parameters, double* residuals,
                double** jacobians) const override {
    for (int c = 0; c < 3; ++c) {
      residuals[c] = 0.0;
      for (int t = 0; t < terms_; ++t) residuals[c] += w_[t] * parameters[t][c];
    }
    if (jacobians)
      for (int t = 0; t < terms_; ++t)
        if (jacobians[t])
          for (int r = 0; r < 3; ++r)
            for (int c = 0; c < 3; ++c) jacobians[t][3 * r + c] = r == c ? w_[t] : 0.0;
    return true;
  }

 private:
  double w_[4];
  int terms_;
};

// Step 3: one Ceres solve on the subsample; returns the iterations used.
int JointRefinement(const SplineStructure& s, const std::vector<Vec>& points,
                    const std::vector<size_t>& sample, double lambda,
                    const SurfaceFitOptions& o, std::vector<double>* control,
                    std::vector<Eigen::Vector2d>* uv) {
  const int p = s.degree[0], q = s.degree[1], nv = s.count[1];
  ceres::Problem::Options problem_options;
  problem_options.cost_function_ownership = ceres::TAKE_OWNERSHIP;
  ceres::Problem problem(problem_options);
  auto* ordering = new ceres::ParameterBlockOrdering;
  std::vector<Eigen::Vector2d> local(sample.size());
  for (size_t t = 0; t < sample.size(); ++t) {
    const size_t k = sample[t];
    local[t] = (*uv)[k];
    const int su = FindSpan(p, s.count[0], s.knots[0].data(), local[t][0]);
    const int sv = FindSpan(q, nv, s.knots[1].data(), local[t][1]);
    std::vector<double*> blocks = {local[t].data()};
    for (int a = 0; a <= p; ++a)
      for (int b = 0; b <= q; ++b) blocks.push_back(control->data() + 3 * ((su - p + a) * nv + (sv - q + b)));
    problem.AddResidualBlock(new SurfacePointCost(&s, points[k], su, sv), nullptr, blocks);
    problem.SetParameterLowerBound(local[t].data(), 0, s.knots[0][su]);
    problem.SetParameterUpperBound(local[t].data(), 0, s.knots[0][su + 1]);
    problem.SetParameterLowerBound(local[t].data(), 1, s.knots[1][sv]);
    problem.SetParameterUpperBound(local[t].data(), 1, s.knots[1][sv + 1]);
    ordering->AddElementToGroup(local[t].data(), 0);
  }
  const double root = std::sqrt(lambda);
  SmoothingRows(s.count[0], nv, [&](const int* idx, const double* w, int terms) {
    std::vector<double*> blocks;
    for (int t = 0; t < terms; ++t) blocks.push_back(control->data() + 3 * idx[t]);
    problem.AddResidualBlock(new SmoothingCost(w, terms, root), nullptr, blocks);
  });
  for (int c = 0; c < s.count[0] * nv; ++c)
    if (problem.HasParameterBlock(control->data() + 3 * c))
      ordering->AddElementToGroup(control->data() + 3 * c, 1);
  ceres::Solver::Options options;
  options.linear_solver_type = ceres::SPARSE_SCHUR;
  options.linear_solver_ordering.reset(ordering);
  options.max_num_iterations = o.max_iterations;
  options.num_threads = ThreadCountOrDefault(o.num_threads);
  options.function_tolerance = 1e-10;
  options.logging_type = ceres::SILENT;
  ceres::Solver::Summary summary;
  ceres::Solve(options, &problem, &summary);
  for (size_t t = 0; t < sample.size(); ++t) (*uv)[sample[t]] = local[t];
  return static_cast<int>(summary.iterations.size());
}

}  // namespace

bool SurfaceFitOptions::IsValid(std::string* error) const {
  if (degree < 1 || degree > SplineLimits::kMaxDegree) {
    *error = "the degree must be in 1.." + std::to_string(SplineLimits::kMaxDegree);
    return false;
  }
  if (count_u < degree + 1 || count_v < degree + 1 ||
      count_u > SplineLimits::kMaxControlPointsPerAxis ||
      count_v > SplineLimits::kMaxControlPointsPerAxis ||
      static_cast<long long>(count_u) * count_v > SplineLimits::kMaxControlPoints) {
    *error = "the grid needs degree + 1 .. " +
             std::to_string(SplineLimits::kMaxControlPointsPerAxis) +
             " control points per direction (at most " +
             std::to_string(SplineLimits::kMaxControlPoints) + " in all)";
    return false;
  }
  if (!(smoothing >= 0.0) || !std::isfinite(smoothing) || correction_rounds < 0 ||
      refine_rounds < 0 || refine_points < 1 || max_iterations < 1) {
    *error = "invalid smoothing, rounds, points or iterations";
    return false;
  }
  return true;
}

Model SurfaceFitResult::ToModel() const {
  SurfaceFitOptions o;
  o.degree = degree;
  o.count_u = count_u;
  o.count_v = count_v;
  Model m;
  m.AddBSplineSurface(Structure(o), control_points);
  return m;
}

SurfaceFitResult FitBSplineSurface(const std::vector<Vec>& points, const std::vector<Vec>& normals,
                                   const SurfaceFitOptions& o) {
  const auto start_time = std::chrono::steady_clock::now();
  SurfaceFitResult r;
  r.points = points.size();
  r.degree = o.degree;
  r.count_u = o.count_u;
  r.count_v = o.count_v;
  auto fail = [&](const std::string& message) {
    r.success = false;
    r.message = message;
    r.termination = FitTermination::kFailure;
    return r;
  };
  std::string error;
  if (!o.IsValid(&error)) return fail(error);
  if (!normals.empty() && normals.size() != points.size())
    return fail("one normal per point is needed");
  const long long unknowns = static_cast<long long>(o.count_u) * o.count_v;
  if (static_cast<long long>(points.size()) < unknowns)
    return fail("fewer points (" + std::to_string(points.size()) + ") than control points (" +
                std::to_string(unknowns) + ")");
  const int threads = ThreadCountOrDefault(o.num_threads);
  const SplineStructure s = Structure(o);
  ParameterFrame frame;
  try {
    frame = FitParameterFrame(points, normals);
  } catch (const std::invalid_argument& e) {
    return fail(e.what());
  }
  r.parameters.resize(points.size());
  for (size_t k = 0; k < points.size(); ++k) {
    const Eigen::Vector2d t = frame.Parameters(points[k]);
    r.parameters[k] = t.cwiseMax(0.0).cwiseMin(1.0);
  }
  const double lambda = o.smoothing * static_cast<double>(points.size()) / unknowns;
  if (!LinearControlPoints(s, points, r.parameters, lambda, &r.control_points))
    return fail("the linear start failed (degenerate points)");
  double rms = Project(s, r.control_points, points, true, threads, &r.parameters);
  r.initial_rms = rms;
  for (int round = 0; round < o.correction_rounds; ++round) {  // step 2
    std::vector<double> next;
    if (!LinearControlPoints(s, points, r.parameters, lambda, &next)) break;
    std::vector<Eigen::Vector2d> uv = r.parameters;
    const double next_rms = Project(s, next, points, false, threads, &uv);
    if (!(next_rms < rms)) break;
    const bool small = next_rms > 0.99 * rms;
    r.control_points.swap(next);
    r.parameters.swap(uv);
    rms = next_rms;
    ++r.correction_rounds;
    if (small) break;
  }
  rms = Project(s, r.control_points, points, true, threads, &r.parameters);
  std::vector<size_t> sample;  // step 3's subsample: every stride-th point
  const size_t stride = (points.size() + o.refine_points - 1) / o.refine_points;
  for (size_t k = 0; k < points.size(); k += stride) sample.push_back(k);
  for (int round = 0; round < o.refine_rounds; ++round) {
    std::vector<double> control = r.control_points;
    std::vector<Eigen::Vector2d> uv = r.parameters;
    r.refine_iterations += JointRefinement(s, points, sample, lambda, o, &control, &uv);
    const double next_rms = Project(s, control, points, true, threads, &uv);
    if (!(next_rms < rms)) break;
    r.refined = true;
    const bool small = next_rms > 0.99 * rms;
    r.control_points.swap(control);
    r.parameters.swap(uv);
    rms = next_rms;
    if (small) break;
  }
  // Step 4: signed distances from the node itself, normals at the feet.
  const Model model = r.ToModel();
  r.residuals.assign(points.size(), 0.0);
  std::vector<double> angles(points.size(), 0.0);
  ParallelFor(points.size(), threads, [&](size_t begin, size_t end) {
    for (size_t k = begin; k < end; ++k) {
      r.residuals[k] = model.Value(points[k]);
      if (normals.empty()) continue;
      double d[kMaxSplineDerivative + 1][kMaxSplineDerivative + 1][3];
      SurfaceDerivatives(s, r.control_points.data(), r.parameters[k][0], r.parameters[k][1], 1, d);
      const Vec n = Vec(d[1][0][0], d[1][0][1], d[1][0][2]).cross(Vec(d[0][1][0], d[0][1][1], d[0][1][2]));
      const double c = n.norm() > 0 ? n.normalized().dot(normals[k]) : 1.0;
      angles[k] = std::acos(std::clamp(c, -1.0, 1.0)) * 180.0 / M_PI;
    }
  });
  double sum = 0.0, angle = 0.0;
  for (size_t k = 0; k < points.size(); ++k) {
    sum += r.residuals[k] * r.residuals[k];
    angle += angles[k];
  }
  r.rms = std::sqrt(sum / points.size());
  if (!normals.empty()) r.mean_normal_angle_deg = angle / points.size();
  if (!std::isfinite(r.rms)) return fail("the fit diverged (non-finite residuals)");
  r.success = true;
  r.termination = FitTermination::kConverged;
  r.message = "converged";
  r.seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start_time).count();
  return r;
}

}  // namespace implicitfit
