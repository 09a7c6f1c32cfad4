#include "fit/bernstein/bernstein_mesh_fitter.h"

#include <ceres/ceres.h>

#include <Eigen/Geometry>
#include <Eigen/SparseCore>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <memory>
#include <optional>

#include "fit/bernstein/adaptive_mesh_fitter.h"
#include "fit/bernstein/continuity_projection.h"
#include "fit/bernstein/domain_least_squares.h"
#include "fit/bernstein/empty_space_sign_guard.h"
#include "fit/bernstein/far_field_rows.h"
#include "fit/bernstein/patch_fitter.h"
#include "fit/bernstein/reused_cholesky.h"
#include "fit/bernstein/winding_number.h"
#include "model/bernstein/bernstein_conversion.h"
#include "model/certificates/bernstein_mesh_certificate.h"
#include "model/bernstein/bernstein_mesh_continuity.h"
#include "model/certificates/convexity_certificate.h"

namespace implicitfit {
namespace {

using Vec = Eigen::Vector3d;
using SparseMatrix = Eigen::SparseMatrix<double>;

// Geometric and normal residuals of one point in its tetrahedron (as PatchPointResidual).
template <int N>
struct MeshPointResidual {
  int degree;
  Tetrahedron tet;
  double x[3], n[3];
  double w;
  template <typename T>
  bool operator()(const T* b, T* r) const {
    using std::sqrt;
    const T xt[3] = {T(x[0]), T(x[1]), T(x[2])};
    Eigen::Matrix<T, 3, 1> g;
    const T f = BernsteinPatch::Derivatives(degree, tet, b, xt, &g);
    const T gn = sqrt(g.squaredNorm() + 1e-24);
    r[0] = f / gn;
    const double s =
        ValueOf(g[0]) * n[0] + ValueOf(g[1]) * n[1] + ValueOf(g[2]) * n[2] < 0 ? -1.0 : 1.0;
    for (int c = 0; c < 3; ++c) r[1 + c] = w * (g[c] / gn - s * n[c]);
    return true;
  }
};

// Linear rows r = weight * (A_u b_u + A_t b_t) between two tetrahedra (continuity or C2 rows of
// one face); constant Jacobian.
class FaceRowsCost final : public ceres::CostFunction {
 public:
  FaceRowsCost(Eigen::MatrixXd a_u, Eigen::MatrixXd a_t)
      : a_u_(std::move(a_u)), a_t_(std::move(a_t)) {
    set_num_residuals(static_cast<int>(a_u_.rows()));
    mutable_parameter_block_sizes()->push_back(static_cast<int>(a_u_.cols()));
    mutable_parameter_block_sizes()->push_back(static_cast<int>(a_t_.cols()));
  }
  bool Evaluate(double const* const* p, double* residuals, double** jacobians) const override {
    const long n = a_u_.cols();
    Eigen::Map<Eigen::VectorXd> r(residuals, a_u_.rows());
    r = a_u_ * Eigen::Map<const Eigen::VectorXd>(p[0], n) +
        a_t_ * Eigen::Map<const Eigen::VectorXd>(p[1], n);
    if (jacobians) {
      using RowMajor = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
      if (jacobians[0]) Eigen::Map<RowMajor>(jacobians[0], a_u_.rows(), n) = a_u_;
      if (jacobians[1]) Eigen::Map<RowMajor>(jacobians[1], a_t_.rows(), n) = a_t_;
    }
    return true;
  }

 private:
  Eigen::MatrixXd a_u_, a_t_;
};

// One linear row r = weight (B(tau)^T b_t - target): the offset equations f(p +- d n) = +-d of
// the initialisation, kept in the refinement with a small weight to fix the scale of f (the
// geometric residuals are invariant under f -> s f, and the continuity rows would otherwise be
// lowered by shrinking f towards 0).
class LinearRowCost final : public ceres::CostFunction {
 public:
  LinearRowCost(std::vector<double> row, double target) : row_(std::move(row)), target_(target) {
    set_num_residuals(1);
    mutable_parameter_block_sizes()->push_back(static_cast<int>(row_.size()));
  }
  bool Evaluate(double const* const* p, double* residuals, double** jacobians) const override {
    double s = -target_;
    for (size_t j = 0; j < row_.size(); ++j) s += row_[j] * p[0][j];
    residuals[0] = s;
    if (jacobians && jacobians[0]) std::copy(row_.begin(), row_.end(), jacobians[0]);
    return true;
  }

 private:
  std::vector<double> row_;
  double target_;
};

// Rejects (returns false) when the tetrahedron's smallest A^mu eigenvalue is below margin.
class MeshConvexityGuard final : public ceres::CostFunction {
 public:
  MeshConvexityGuard(int k, int n, double margin) : k_(k), n_(n), margin_(margin) {
    set_num_residuals(1);
    mutable_parameter_block_sizes()->push_back(n);
  }
  bool Evaluate(double const* const* p, double* residuals, double** jacobians) const override {
    residuals[0] = 0.0;
    if (jacobians && jacobians[0]) std::fill(jacobians[0], jacobians[0] + n_, 0.0);
    const ConvexityCertificate c = CertifyConvexity(k_, p[0]);
    return c.convex && c.min_eigenvalue >= margin_;
  }

 private:
  int k_, n_;
  double margin_;
};

// Groups the rows of `rows` (selected by keep) by their pair of tetrahedra into dense blocks.
std::map<std::pair<long long, long long>, std::pair<Eigen::MatrixXd, Eigen::MatrixXd>> FaceBlocks(
    const ContinuityRows& rows, int n, double weight, const std::vector<bool>* keep) {
  std::map<std::pair<long long, long long>, std::vector<int>> by_face;
  for (int r = 0; r < rows.C.rows(); ++r)
    if (!keep || (*keep)[r]) by_face[rows.tetrahedra[r]].push_back(r);
  std::map<std::pair<long long, long long>, std::pair<Eigen::MatrixXd, Eigen::MatrixXd>> out;
  for (const auto& [face, list] : by_face) {
    Eigen::MatrixXd au = Eigen::MatrixXd::Zero(list.size(), n), at = au;
    for (size_t i = 0; i < list.size(); ++i)
      for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(rows.C, list[i]); it;
           ++it) {
        const long long tet = it.col() / n;
        const int j = static_cast<int>(it.col() % n);
        (tet == face.first ? au : at)(static_cast<long>(i), j) += weight * it.value();
      }
    out.emplace(face, std::make_pair(au, at));
  }
  return out;
}

struct PointData {
  std::vector<long long> tet;  // tetrahedron of each point
  std::vector<int> count;      // points per tetrahedron
};

PointData LocatePoints(const BernsteinGrid& grid, const std::vector<Vec>& points) {
  PointData d;
  d.count.assign(static_cast<size_t>(grid.NumTetrahedra()), 0);
  for (const Vec& p : points) {
    double tau[4];
    d.tet.push_back(grid.Locate(p.data(), tau));
    ++d.count[d.tet.back()];
  }
  return d;
}

// C2 rows (j = 2) on faces with a tetrahedron that holds no point.
std::vector<bool> EmptyFaceRows(const ContinuityRows& c2, const PointData& data) {
  std::vector<bool> keep(c2.tetrahedra.size());
  for (size_t r = 0; r < keep.size(); ++r)
    keep[r] = data.count[c2.tetrahedra[r].first] == 0 || data.count[c2.tetrahedra[r].second] == 0;
  return keep;
}

void AddFarFieldRows(const std::vector<FarFieldRow>& rows, double weight,
                     DomainLeastSquares* solver) {
  for (const FarFieldRow& r : rows) solver->AddValueRow(r.x, weight * r.weight, r.target);
}

// Step 1: f(p_i) = 0, f(p_i +- d n_i) = +-d. Returns b (not yet projected).
std::vector<double> LinearInitialisation(const std::vector<Vec>& points,
                                         const std::vector<Vec>& normals, double d,
                                         const std::vector<FarFieldRow>& far, double far_weight,
                                         DomainLeastSquares* solver) {
  AddFarFieldRows(far, far_weight, solver);
  for (size_t i = 0; i < points.size(); ++i) {
    solver->AddValueRow(points[i], 1.0, 0.0);
    solver->AddValueRow(points[i] + d * normals[i], 1.0, d);
    solver->AddValueRow(points[i] - d * normals[i], 1.0, -d);
  }
  return solver->Solve();
}

double MeshRms(const BernsteinGrid& grid, int k, const std::vector<double>& b,
               const std::vector<Vec>& points, const std::vector<Vec>& normals,
               double* mean_angle) {
  const long long n = NumBernsteinControlPoints(k);
  double ss = 0, angles = 0;
  for (size_t i = 0; i < points.size(); ++i) {
    double tau[4];
    const long long t = grid.Locate(points[i].data(), tau);
    Vec g;
    const double f = BernsteinPatch::Derivatives(k, grid.TetrahedronOf(t), b.data() + t * n,
                                                 points[i].data(), &g);
    ss += f * f / std::max(g.squaredNorm(), 1e-300);
    if (!normals.empty())
      angles += std::acos(std::min(1.0, std::abs(g.normalized().dot(normals[i])))) * 180 / M_PI;
  }
  if (mean_angle)
    *mean_angle = normals.empty() ? -1.0 : angles / std::max<size_t>(1, points.size());
  return std::sqrt(ss / std::max<size_t>(1, points.size()));
}

// The factor of the normal rows of a point in tetrahedron t: sharp_normal_factor in a crease
// tetrahedron when the normals were estimated (MeshFitOptions::normals_estimated), else 1.
double NormalRowFactor(const BernsteinGrid& grid, long long t, const MeshFitOptions& options) {
  const bool crease = !grid.sharp.empty() && grid.sharp[static_cast<size_t>(t)] != 0;
  return options.normals_estimated && crease ? options.sharp_normal_factor : 1.0;
}

// Step 2 (unconstrained): Gauss-Newton on the geometric residual f/|grad f| with the gradient
// norm g_i frozen at the current iterate (a linear problem: iteratively reweighted least
// squares, each iteration one DomainLeastSquares solve). Rows per point: c_i f(p_i)/g_i (c_i the
// Cauchy weight 1/sqrt(1 + (r_i/s)^2), s = loss_factor x current RMS), the normal rows
// w_n (grad f(p_i)/g_i - n_i) and the offset rows w_s (f(p_i +- d n_i) -+ d) that fix the
// scale of f. Stops when the RMS improves by less than 0.5% or after max_iterations; returns
// the best iterate (never worse than the start). Iterations used in *iterations.
std::vector<double> RefineLinearised(const BernsteinGrid& grid, int k,
                                     const std::vector<Vec>& points,
                                     const std::vector<Vec>& normals, double d,
                                     const MeshFitOptions& options, std::vector<double> b,
                                     const std::vector<FarFieldRow>& far, double* far_weight_io,
                                     const std::vector<FarFieldRow>& pins,
                                     DomainLeastSquares* solver, int* iterations) {
  double far_weight = *far_weight_io;
  const long long n = NumBernsteinControlPoints(k);
  const double normal_weight = options.normal_weight * 10 * d;  // normal_weight x diagonal / 10
  constexpr double scale_weight = 0.1, loss_factor = 3.0;
  // The far-field relaxation (header, step 2): the weight of the far-field rows, lowered by
  // far_field_relaxation whenever a stage stalls, down to far_field_floor x the start weight;
  // the sign guard (fit/bernstein/empty_space_sign_guard.h) made at the first lowering.
  const bool relax = !far.empty() && options.far_field_relaxation > 0 &&
                     options.far_field_relaxation < 1 && options.far_field_floor < 1;
  const double start_far_weight = options.far_field_weight;
  const double lowest_far_weight = options.far_field_floor * start_far_weight;
  std::unique_ptr<EmptySpaceSignGuard> guard;
  if (far_weight < start_far_weight) {  // starting relaxed (a finer round of the adaptive fit)
    guard = std::make_unique<EmptySpaceSignGuard>(grid, points, 2 * d, options.sign_guard_samples);
    guard->Record(k, b);
  }
  bool stage_improved = false;
  double best_far_weight = far_weight;  // the far-field weight of the best iterate's stage
  double rms = MeshRms(grid, k, b, points, normals, nullptr);
  std::vector<double> best = b;
  double best_rms = rms;
  *iterations = 0;
  const long long start_errors = FarFieldSignErrors(grid, k, b, far);
  const long long start_pin_errors = FarFieldSignErrors(grid, k, b, pins);
  for (int it = 0; it < options.max_iterations; ++it) {
    const double s = loss_factor * rms;
    AddFarFieldRows(far, far_weight, solver);
    AddFarFieldRows(pins, start_far_weight, solver);  // never relaxed
    for (size_t i = 0; i < points.size(); ++i) {
      double tau[4];
      const long long t = grid.Locate(points[i].data(), tau);
      Vec g;
      const double f = BernsteinPatch::Derivatives(k, grid.TetrahedronOf(t), b.data() + t * n,
                                                   points[i].data(), &g);
      const double wn = normal_weight * NormalRowFactor(grid, t, options);
      const double gn = std::max(g.norm(), 1e-12);
      const double r = f / gn;
      const double c = s > 0 ? 1.0 / std::sqrt(1.0 + (r / s) * (r / s)) : 1.0;
      if (options.exact_linearisation && far_weight < start_far_weight) {
        // r = f/|g| is homogeneous of degree 0 in b, so J b_0 = 0 and the linearised residual
        // r_0 + J (b - b_0) = 0 is the row J b = -r_0 with
        // J = B(p)/|g| - (f/|g|^3) g . grad B(p); for u = g/|g|, J_u = (I - u u^T) grad B / |g|,
        // again J_u b_0 = 0, so the rows J_u b = n - u (n oriented as u).
        const Vec u = g / gn;
        DomainLeastSquares::PointRow rows[4];
        rows[0] = {c, 1.0 / gn, -(f / (gn * gn * gn)) * g, -r};
        const Eigen::Matrix3d projector = (Eigen::Matrix3d::Identity() - u * u.transpose()) / gn;
        const double sign = g.dot(normals[i]) < 0 ? -1.0 : 1.0;
        for (int a = 0; a < 3; ++a)
          rows[1 + a] = {wn * c, 0.0, projector.row(a).transpose(),
                         sign * normals[i][a] - u[a]};
        solver->AddPointRows(points[i], rows, wn > 0 ? 4 : 1);
      } else {
        solver->AddValueRow(points[i], c / gn, 0.0);
        if (wn > 0) solver->AddGradientRows(points[i], wn * c / gn, gn * normals[i]);
      }
      solver->AddValueRow(points[i] + d * normals[i], scale_weight, d);
      solver->AddValueRow(points[i] - d * normals[i], scale_weight, -d);
    }
    const std::vector<double> full = solver->Solve();
    ++*iterations;
    // Backtracking along the step (the frozen-gradient problem can overshoot where |grad f|
    // changes fast): halve it up to 4 times until the RMS decreases without adding far-field
    // sign errors (a spurious sheet) to those of the start.
    double next = rms;
    bool admissible = false;
    std::vector<double> trial(b.size());
    for (double step = 1.0; step >= 1.0 / 16; step *= 0.5) {
      for (size_t j = 0; j < b.size(); ++j) trial[j] = b[j] + step * (full[j] - b[j]);
      next = MeshRms(grid, k, trial, points, normals, nullptr);
      // (The guard only for a step that would be taken: it costs more than the RMS.)
      admissible = FarFieldSignErrors(grid, k, trial, far) <= start_errors &&
                   FarFieldSignErrors(grid, k, trial, pins) <= start_pin_errors &&
                   (!guard || !(next < rms) || guard->Changes(k, trial) == 0);
      if (next < rms && admissible) break;
    }
    b = trial;
    if (next < best_rms && admissible) {
      best = b;
      best_rms = next;
      best_far_weight = far_weight;
      stage_improved = true;
    }
    // A relaxed stage (guard made) also ends when no step length is admissible.
    if (!(next < 0.995 * rms) || (guard && !admissible)) {
      // Stalled: the next, lighter stage from the best iterate, while the last stage improved
      // (a stage whose steps were all rejected, e.g. by the guard, ends the relaxation).
      if (relax && stage_improved &&
          far_weight * options.far_field_relaxation >= lowest_far_weight * (1 - 1e-12)) {
        if (!guard) {
          guard = std::make_unique<EmptySpaceSignGuard>(grid, points, 2 * d,
                                                        options.sign_guard_samples);
          guard->Record(k, best);
        }
        far_weight *= options.far_field_relaxation;
        b = best;
        rms = best_rms;
        stage_improved = false;
        continue;
      }
      break;
    }
    rms = next;
  }
  *far_weight_io = best_far_weight;
  return best;
}

template <int N>
ceres::CostFunction* PointCost(int k, const Tetrahedron& tet, const Vec& x, const Vec& normal,
                               double w) {
  auto* f =
      new MeshPointResidual<N>{k, tet, {x[0], x[1], x[2]}, {normal[0], normal[1], normal[2]}, w};
  return new ceres::AutoDiffCostFunction<MeshPointResidual<N>, 4, N>(f);
}

ceres::CostFunction* AnyPointCost(int k, const Tetrahedron& tet, const Vec& x, const Vec& normal,
                                  double w) {
  switch (k) {
    case 2:
      return PointCost<10>(k, tet, x, normal, w);
    case 3:
      return PointCost<20>(k, tet, x, normal, w);
    case 4:
      return PointCost<35>(k, tet, x, normal, w);
    default:
      return PointCost<56>(k, tet, x, normal, w);
  }
}

// Step 2 (and the guarded step of 3). Refines b in place; returns the iterations used.
int Refine(const BernsteinGrid& grid, int k, int continuity, const std::vector<Vec>& points,
           const std::vector<Vec>& normals, const PointData& data, const ContinuityRows& c2,
           const std::vector<bool>& c2_keep, const MeshFitOptions& options, double loss_scale,
           double offset, const std::vector<double>* guard_margins, std::vector<double>* b) {
  const int n = static_cast<int>(NumBernsteinControlPoints(k));
  ceres::Problem::Options po;
  po.loss_function_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
  ceres::Problem problem(po);
  auto loss = std::make_unique<ceres::CauchyLoss>(loss_scale);
  std::vector<Tetrahedron> tets(static_cast<size_t>(grid.NumTetrahedra()));
  for (long long t = 0; t < grid.NumTetrahedra(); ++t) tets[t] = grid.TetrahedronOf(t);
  double* base = b->data();
  for (long long t = 0; t < grid.NumTetrahedra(); ++t) problem.AddParameterBlock(base + t * n, n);
  for (size_t i = 0; i < points.size(); ++i) {
    const long long t = data.tet[i];
    const double wn = options.normal_weight * NormalRowFactor(grid, t, options);
    problem.AddResidualBlock(AnyPointCost(k, tets[t], points[i], normals[i], wn), loss.get(),
                             base + t * n);
  }
  // Scale-fixing offset rows (LinearRowCost), weight kScaleWeight.
  constexpr double kScaleWeight = 0.1;
  std::vector<double> basis(static_cast<size_t>(n));
  for (size_t i = 0; i < points.size(); ++i)
    for (double sign : {1.0, -1.0}) {
      const Vec x = points[i] + sign * offset * normals[i];
      double tau[4];
      const long long t = grid.Locate(x.data(), tau);
      BasisValues(k, tau, basis.data());
      std::vector<double> row(basis);
      for (double& v : row) v *= kScaleWeight;
      problem.AddResidualBlock(new LinearRowCost(std::move(row), kScaleWeight * sign * offset),
                               loss.get(), base + t * n);
    }
  const ContinuityRows rows = BernsteinContinuityRows(grid, k, 0, continuity);
  for (auto& [face, m] : FaceBlocks(rows, n, options.continuity_weight, nullptr))
    problem.AddResidualBlock(new FaceRowsCost(m.first, m.second), nullptr, base + face.first * n,
                             base + face.second * n);
  for (auto& [face, m] : FaceBlocks(c2, n, options.smoothing_weight, &c2_keep))
    problem.AddResidualBlock(new FaceRowsCost(m.first, m.second), nullptr, base + face.first * n,
                             base + face.second * n);
  if (guard_margins)
    for (long long t = 0; t < grid.NumTetrahedra(); ++t)
      problem.AddResidualBlock(new MeshConvexityGuard(k, n, (*guard_margins)[t]), nullptr,
                               base + t * n);
  ceres::Solver::Options so;
  so.linear_solver_type = ceres::SPARSE_NORMAL_CHOLESKY;
  so.max_num_iterations = options.max_iterations;
  so.num_threads = 2;
  ceres::Solver::Summary summary;
  ceres::Solve(so, &problem, &summary);
  return static_cast<int>(summary.iterations.size());
}

// The convex start: the certified degree-2 patch's quadric on every tetrahedron, at degree k.
bool ConvexStart(const BernsteinGrid& grid, int k, const std::vector<Vec>& points,
                 const std::vector<Vec>& normals, std::vector<double>* b, std::string* message) {
  PatchFitOptions po;
  po.degree = 2;
  po.convex = true;
  const PatchFitResult quadric_fit = FitBernsteinPatch(points, normals, po);
  if (!quadric_fit.success || !quadric_fit.certified_convex) {
    *message = "the convex degree-2 start failed: " + quadric_fit.message;
    return false;
  }
  const CartesianQuadric q =
      BernsteinToQuadric(quadric_fit.control_points.data(), quadric_fit.tetrahedron);
  b->clear();
  for (long long t = 0; t < grid.NumTetrahedra(); ++t) {
    const std::vector<double> bt = QuadricToBernstein(q, grid.TetrahedronOf(t), k);
    b->insert(b->end(), bt.begin(), bt.end());
  }
  return true;
}

}  // namespace

bool MeshFitOptions::IsValid(std::string* error) const {
  auto fail = [&](const std::string& e) {
    if (error) *error = e;
    return false;
  };
  if (degree < 2 || degree > 5) return fail("degree must be 2..5 for a patch mesh");
  if (continuity != 0 && continuity != 1) return fail("continuity must be 0 or 1");
  if (convex && continuity != 1)
    return fail("convex needs continuity 1 (convex patches joined C0 can meet at a concave kink)");
  if (convex && adaptive && max_levels > 0)
    return fail(
        "convex needs a uniform grid (no refinement levels: the certificate wants C1 on every "
        "face)");
  if (cells < 0 || cells > 200) return fail("cells must be in 1..200");
  if (!(cell >= 0.0) || !std::isfinite(cell)) return fail("cell must be a positive length");
  if (!(far_field_beside_cos >= 0.0 && far_field_beside_cos < 1.0))
    return fail("far_field_beside_cos must be in [0, 1)");
  if (!(box_margin >= 0.0 && box_margin <= 10.0)) return fail("box_margin must be in [0, 10]");
  if (!(far_field_ramp >= 0.0 && std::isfinite(far_field_ramp)))
    return fail("far_field_ramp must be >= 0 (cubes)");
  if (!(far_field_ramp_power > 0.0 && std::isfinite(far_field_ramp_power)))
    return fail("far_field_ramp_power must be positive");
  if (!(far_field_relaxation >= 0.0 && far_field_relaxation <= 1.0))
    return fail("far_field_relaxation must be in [0, 1]");
  if (!(far_field_floor >= 0.0 && far_field_floor <= 1.0))
    return fail("far_field_floor must be in [0, 1]");
  if (sign_guard_samples < 1 || sign_guard_samples > 16)
    return fail("sign_guard_samples must be in 1..16");
  if (!(noise >= 0.0 && std::isfinite(noise))) return fail("noise must be >= 0 (0: estimated)");
  if (!(refine_factor > 0.0 && std::isfinite(refine_factor)))
    return fail("refine_factor must be positive");
  if (!(refine_spacing_floor >= 0.0 && std::isfinite(refine_spacing_floor)))
    return fail("refine_spacing_floor must be >= 0");
  if (!(min_leaf_spacings >= 0.0 && std::isfinite(min_leaf_spacings)))
    return fail("min_leaf_spacings must be >= 0");
  if (round_retries < 0 || round_retries > 8) return fail("round_retries must be in 0..8");
  if (max_levels < 0 || max_levels > kMaxRefinementLevel)
    return fail("max_levels must be in 0.." + std::to_string(kMaxRefinementLevel));
  if (max_unknowns < 1) return fail("max_unknowns must be >= 1");
  if (!(feature_angle_deg > 0.0 && feature_angle_deg < 180.0))
    return fail("feature_angle_deg must be in (0, 180)");
  if (!(soft_c1_weight >= 0.0 && std::isfinite(soft_c1_weight)))
    return fail("soft_c1_weight must be >= 0");
  if (!(soft_c1_sharp_factor >= 0.0 && std::isfinite(soft_c1_sharp_factor)))
    return fail("soft_c1_sharp_factor must be >= 0");
  if (!(sharp_normal_factor >= 0.0 && std::isfinite(sharp_normal_factor)))
    return fail("sharp_normal_factor must be >= 0");
  return true;
}

BernsteinGrid MeshGridForCloud(const std::vector<Vec>& points, int cells, double cell,
                               double margin) {
  Vec lo = Vec::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  for (const Vec& p : points) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  Vec ext = hi - lo;
  const double longest = std::max(ext.maxCoeff(), 1e-12);
  for (int a = 0; a < 3; ++a) {  // +5% each side, at least margin x the longest extent
    ext[a] = std::max(ext[a], 0.05 * longest);
    ext[a] += 2 * std::max(0.05 * ext[a], margin * longest);
  }
  const Vec center = 0.5 * (lo + hi);
  BernsteinGrid g;
  g.cell = cell > 0.0 ? cell : ext.maxCoeff() / (cells > 0 ? cells : 4);
  for (int a = 0; a < 3; ++a)  // in double: --cell 1e-9 must not overflow to a 1x1x1 grid
    g.cells[a] = static_cast<int>(std::clamp(std::ceil(ext[a] / g.cell - 1e-9), 1.0, 1e9));
  g.origin = center - 0.5 * g.cell * Vec(g.cells[0], g.cells[1], g.cells[2]);
  return g;
}

std::string MeshFitSizeProblem(const BernsteinGrid& grid, int degree) {
  char text[320];
  std::snprintf(text, sizeof text,
                "a patch mesh of %d x %d x %d cubes of degree %d has %.3g distinct control points, "
                "more than the limit of %.0f (memory and time grow faster than their square: "
                "12^3 cubes took 2.8 GB); use fewer --cells or a larger --cell",
                grid.cells[0], grid.cells[1], grid.cells[2], degree,
                MeshFitControlPoints(grid, degree), kMaxMeshFitControlPoints);
  return text;
}

BernsteinGrid MeshFitGrid(const std::vector<Vec>& points, const MeshFitOptions& options) {
  if (options.has_grid) return options.grid;
  return MeshGridForCloud(points, options.cells > 0 ? options.cells : (options.convex ? 4 : 8),
                          options.cell, options.convex ? 0.0 : options.box_margin);
}

double MeshFitControlPoints(const BernsteinGrid& grid, int degree) {
  double n = 1.0;
  for (int a = 0; a < 3; ++a) n *= static_cast<double>(degree) * grid.cells[a] + 1.0;
  return n;
}

Model MeshFitResult::ToModel() const {
  Model m;
  m.AddBernsteinMesh(degree, grid, continuity, control_points);
  return m;
}

MeshFitResult FitBernsteinMesh(const std::vector<Vec>& points, const std::vector<Vec>& normals,
                               const MeshFitOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  MeshFitResult result;
  std::string error;
  if (!options.IsValid(&error)) {
    result.message = error;
    return result;
  }
  if (normals.size() != points.size() || points.size() < 10) {
    result.message = "a patch mesh needs at least 10 points with normals";
    return result;
  }
  {
    Eigen::AlignedBox3d box;
    for (const Vec& p : points) box.extend(p);
    if (!(box.diagonal().norm() > 0) || !std::isfinite(box.diagonal().norm())) {
      result.message = "the points span no finite box (they all coincide): no surface to fit";
      return result;
    }
  }
  const BernsteinGrid grid = MeshFitGrid(points, options);
  result = options.adaptive && !options.convex
               ? FitAdaptiveBernsteinMesh(points, normals, options, grid)
               : FitBernsteinMeshOnGrid(points, normals, options, grid, nullptr);
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

MeshFitResult FitBernsteinMeshOnGrid(const std::vector<Vec>& points,
                                     const std::vector<Vec>& normals,
                                     const MeshFitOptions& options, const BernsteinGrid& fit_grid,
                                     const MeshFitStart* fit_start) {
  MeshFitResult result;
  const int k = options.degree;
  const long long n = NumBernsteinControlPoints(k);
  result.degree = k;
  result.continuity = options.continuity;
  result.grid = fit_grid;
  const BernsteinGrid& grid = result.grid;
  if (MeshFitControlPoints(grid, k) > kMaxMeshFitControlPoints) {
    result.message = MeshFitSizeProblem(grid, k);
    return result;
  }
  result.tetrahedra = grid.NumTetrahedra();
  ProgressStage stage(options.progress, "patch-mesh fit",
                      std::to_string(grid.NumTetrahedra()) + " patches" +
                          (grid.MaxLevel() > 0 ? ", " + std::to_string(grid.NumLeaves()) +
                                                     " leaves over " +
                                                     std::to_string(grid.MaxLevel()) +
                                                     (grid.MaxLevel() == 1 ? " level" : " levels")
                                               : ""));
  const double diagonal = (grid.BoxMax() - grid.BoxMin()).norm();
  const double d = 0.01 * diagonal;

  const PointData data = LocatePoints(grid, points);
  const ContinuityRows c2 = BernsteinContinuityRows(grid, k, 2, 2);
  const std::vector<bool> c2_keep = EmptyFaceRows(c2, data);
  // Continuity 0: the C1 rows as penalties (header, "Soft C1"); the projector stays C0.
  const bool soft_c1 = options.continuity == 0 && options.soft_c1_weight > 0;
  DomainLeastSquares solver(grid, k, soft_c1 ? 1 : options.continuity,
                            soft_c1 ? options.soft_c1_weight : options.continuity_weight,
                            options.smoothing_weight, c2, c2_keep,
                            soft_c1 ? options.soft_c1_weight * options.soft_c1_sharp_factor : -1);
  const ContinuityProjector projector(grid, k, options.continuity);
  // far_field_weight = 0 switches the far-field rows (and the fallback's sign check) off.
  std::vector<FarFieldRow> far;
  if (options.far_field_weight > 0) {
    std::optional<WindingNumber> winding;
    if (options.far_field_winding) winding.emplace(points, normals);
    far = FarFieldRows(grid, points, normals, 2 * d, options.far_field_beside_cos,
                       options.far_field_ramp, options.far_field_ramp_power,
                       winding ? &*winding : nullptr);
  }
  double far_weight = options.far_field_weight;
  static const std::vector<FarFieldRow> no_pins;
  const std::vector<FarFieldRow>& pins = fit_start ? fit_start->pins : no_pins;
  std::vector<double> b;
  if (fit_start) {  // an earlier fit on a coarser grid, re-expressed on this one
    b = fit_start->control_points;
    far_weight = fit_start->far_weight;
  } else {
    b = LinearInitialisation(points, normals, d, far, far_weight, &solver);
  }
  projector.Project(&b);
  result.initial_rms = MeshRms(grid, k, b, points, normals, nullptr);
  const double loss_scale = std::max(3.0 * result.initial_rms, 1e-9 * diagonal);

  // Step 2: the linearised refinement; when it makes no progress (its frozen-gradient steps can
  // point uphill, e.g. on the torus of the tests) the Ceres refinement on the exact residuals,
  // projected, kept when better. Returns the RMS; *defect the continuity defect.
  auto unconstrained = [&](std::vector<double>* b, int* iterations, double* defect) {
    *b = RefineLinearised(grid, k, points, normals, d, options, *b, far, &far_weight, pins,
                          &solver, iterations);
    *defect = projector.Project(b);
    double rms = MeshRms(grid, k, *b, points, normals, nullptr);
    // (Not on grids above 1 500 tetrahedra, where the Ceres fallback takes minutes, nor when the
    // start already fits to rounding.)
    if (!(rms < 0.995 * result.initial_rms) && grid.NumTetrahedra() <= 1500 &&
        result.initial_rms > 1e-9 * diagonal) {
      std::vector<double> polished = *b;
      *iterations += Refine(grid, k, options.continuity, points, normals, data, c2, c2_keep,
                            options, loss_scale, d, nullptr, &polished);
      const double polished_defect = projector.Project(&polished);
      const double polished_rms = MeshRms(grid, k, polished, points, normals, nullptr);
      // Ceres has no far-field rows: keep its result only if it adds no sign error at the
      // far-field points (no spurious sheet in empty space).
      if (polished_rms < rms &&
          FarFieldSignErrors(grid, k, polished, far) <= FarFieldSignErrors(grid, k, *b, far) &&
          FarFieldSignErrors(grid, k, polished, pins) <= FarFieldSignErrors(grid, k, *b, pins)) {
        *b = polished;
        rms = polished_rms;
        *defect = polished_defect;
      }
    }
    return rms;
  };
  if (options.convex) {
    // The unconstrained fit (step 2) for comparison: what the convexity constraint costs.
    std::vector<double> free_fit = b;
    int free_iterations = 0;
    double free_defect = 0;
    result.unconstrained_rms = unconstrained(&free_fit, &free_iterations, &free_defect);
    if (!ConvexStart(grid, k, points, normals, &b, &result.message)) return result;
    std::vector<double> margins(static_cast<size_t>(grid.NumTetrahedra()));
    for (long long t = 0; t < grid.NumTetrahedra(); ++t) {
      double scale = 0;
      for (long long j = 0; j < n; ++j) scale = std::max(scale, std::abs(b[t * n + j]));
      const ConvexityCertificate c = CertifyConvexity(k, b.data() + t * n);
      margins[t] = std::min(1e-4 * scale, 0.5 * c.min_eigenvalue);
    }
    result.iterations = Refine(grid, k, 1, points, normals, data, c2, c2_keep, options, loss_scale,
                               d, &margins, &b);
    result.continuity_defect = projector.Project(&b);
  } else {
    const double rms = unconstrained(&b, &result.iterations, &result.continuity_defect);
    result.kept_initialisation = !(rms < result.initial_rms);
  }
  result.control_points = b;
  result.far_weight = far_weight;
  result.unknowns = solver.unknowns();
  result.box_sign_errors = far.empty() ? -1 : FarFieldSignErrors(grid, k, b, far, true);
  result.rms = MeshRms(grid, k, b, points, normals, &result.mean_normal_angle_deg);
  {
    char rms[48];
    std::snprintf(rms, sizeof rms, "rms %.3g", result.rms);
    stage.End(rms);
  }
  result.min_eigenvalue = std::numeric_limits<double>::infinity();
  for (long long t = 0; t < grid.NumTetrahedra(); ++t) {
    const ConvexityCertificate c = CertifyConvexity(k, b.data() + t * n);
    result.certified_tetrahedra += c.convex;
    result.min_eigenvalue = std::min(result.min_eigenvalue, c.min_eigenvalue);
  }
  result.certified_convex = options.continuity == 1 &&
                            result.certified_tetrahedra == grid.NumTetrahedra() &&
                            result.continuity_defect <= kMaxContinuityDefect;
  if (options.convex && !result.certified_convex) {
    result.message = "the convexity certificate failed after the projection: " +
                     std::to_string(result.certified_tetrahedra) + " of " +
                     std::to_string(grid.NumTetrahedra()) +
                     " tetrahedra certified, continuity defect " +
                     std::to_string(result.continuity_defect);
  } else {
    result.success = true;
    result.message = "converged";
  }
  return result;
}

}  // namespace implicitfit
