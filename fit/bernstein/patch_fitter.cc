#include "fit/bernstein/patch_fitter.h"

#include <ceres/ceres.h>

#include <Eigen/Dense>
#include <algorithm>
#include <chrono>
#include <cmath>

#include "model/bernstein/bernstein_conversion.h"
#include "model/certificates/convexity_certificate.h"
#include "model/certificates/symmetric_eigen3.h"

namespace implicitfit {
namespace {

using Vec = Eigen::Vector3d;

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

// Degree 2, convex by construction: z = [L00 L10 L11 L20 L21 L22, b1001 b0101 b0011 b0002].
// A_ij = b(e_i+e_j) + b(2e_4) - b(e_i+e_4) - b(e_j+e_4)  =>  b(e_i+e_j) = A_ij - b0002 + b_i4 +
// b_j4.
template <typename T>
void ConvexQuadricControlPoints(const T* z, double margin, T* b) {
  const T L[3][3] = {{z[0], T(0.0), T(0.0)}, {z[1], z[2], T(0.0)}, {z[3], z[4], z[5]}};
  T A[3][3];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      A[i][j] = L[i][0] * L[j][0] + L[i][1] * L[j][1] + L[i][2] * L[j][2];
      if (i == j) A[i][j] += margin;
    }
  const T b4[3] = {z[6], z[7], z[8]};
  const T b44 = z[9];
  // docs/design.md order: 2000 1100 1010 1001 0200 0110 0101 0020 0011 0002
  auto pair = [&](int i, int j) { return A[i][j] - b44 + b4[i] + b4[j]; };
  b[0] = pair(0, 0);
  b[1] = pair(0, 1);
  b[2] = pair(0, 2);
  b[3] = b4[0];
  b[4] = pair(1, 1);
  b[5] = pair(1, 2);
  b[6] = b4[1];
  b[7] = pair(2, 2);
  b[8] = b4[2];
  b[9] = b44;
}

struct ConvexQuadricPointResidual {
  PatchPointResidual<10> inner;
  double margin;
  template <typename T>
  bool operator()(const T* z, T* r) const {
    T b[10];
    ConvexQuadricControlPoints(z, margin, b);
    return inner(b, r);
  }
};

// Returns false (step rejected) when some A^mu has its smallest eigenvalue below the margin.
struct ConvexityGuard final : public ceres::CostFunction {
  int degree, n;
  double relative_margin;
  ConvexityGuard(int k, int count, double margin) : degree(k), n(count), relative_margin(margin) {
    set_num_residuals(1);
    mutable_parameter_block_sizes()->push_back(count);
  }
  bool Evaluate(double const* const* p, double* residuals, double** jacobians) const override {
    residuals[0] = 0.0;
    if (jacobians && jacobians[0]) std::fill(jacobians[0], jacobians[0] + n, 0.0);
    double scale = 0.0;
    for (int i = 0; i < n; ++i) scale = std::max(scale, std::abs(p[0][i]));
    const ConvexityCertificate c = CertifyConvexity(degree, p[0]);
    return c.convex && c.min_eigenvalue >= relative_margin * scale;
  }
};

template <int N>
PatchPointResidual<N> MakePointResidual(int k, const Tetrahedron& tet,
                                        const std::vector<Vec>& points,
                                        const std::vector<Vec>& normals, size_t i, double w) {
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

ceres::Solver::Summary SolvePatchProblem(ceres::Problem* problem, int max_iterations) {
  ceres::Solver::Options so;
  so.linear_solver_type = ceres::DENSE_QR;
  so.max_num_iterations = max_iterations;
  so.num_threads = 2;
  ceres::Solver::Summary summary;
  ceres::Solve(so, problem, &summary);
  return summary;
}

std::vector<double> BasisAt(int k, const Tetrahedron& tet, const Vec& x) {
  const int n = static_cast<int>(NumBernsteinControlPoints(k));
  std::vector<double> basis(n), unit(n, 0.0);
  for (int j = 0; j < n; ++j) {
    unit[j] = 1.0;
    basis[j] = BernsteinPatch::Evaluate(k, tet, unit.data(), x.data());
    unit[j] = 0.0;
  }
  return basis;
}

std::vector<double> LinearInitialisation(int k, const Tetrahedron& tet,
                                         const std::vector<Vec>& points,
                                         const std::vector<Vec>& normals, double h) {
  const int n = static_cast<int>(NumBernsteinControlPoints(k));
  const bool with_normals = !normals.empty();
  const int rows_per_point = with_normals ? 3 : 1;
  Eigen::MatrixXd M(points.size() * rows_per_point, n);
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(M.rows());
  for (size_t i = 0; i < points.size(); ++i) {
    const std::vector<double> b0 = BasisAt(k, tet, points[i]);
    M.row(rows_per_point * i) = Eigen::Map<const Eigen::RowVectorXd>(b0.data(), n);
    if (with_normals) {
      const std::vector<double> bp = BasisAt(k, tet, points[i] + h * normals[i]);
      const std::vector<double> bm = BasisAt(k, tet, points[i] - h * normals[i]);
      M.row(3 * i + 1) = Eigen::Map<const Eigen::RowVectorXd>(bp.data(), n);
      M.row(3 * i + 2) = Eigen::Map<const Eigen::RowVectorXd>(bm.data(), n);
      rhs[3 * i + 1] = h;
      rhs[3 * i + 2] = -h;
    }
  }
  const Eigen::VectorXd b = M.colPivHouseholderQr().solve(rhs);
  return std::vector<double>(b.data(), b.data() + n);
}

double Rms(int k, const Tetrahedron& tet, const std::vector<double>& b,
           const std::vector<Vec>& points, const std::vector<Vec>& normals, double* mean_angle,
           double* mean_cosine = nullptr) {
  double ss = 0, angles = 0, cosines = 0;
  for (size_t i = 0; i < points.size(); ++i) {
    Eigen::Vector3d g;
    const double f = BernsteinPatch::Derivatives(k, tet, b.data(), points[i].data(), &g);
    ss += f * f / std::max(g.squaredNorm(), 1e-300);
    if (!normals.empty()) {
      const double cosine = std::clamp(g.normalized().dot(normals[i]), -1.0, 1.0);  // signed
      angles += std::acos(cosine) * 180 / M_PI;
      cosines += cosine;
    }
  }
  if (mean_angle) *mean_angle = normals.empty() ? -1.0 : angles / points.size();
  if (mean_cosine) *mean_cosine = normals.empty() ? 0.0 : cosines / points.size();
  return std::sqrt(ss / points.size());
}

// What a solve ended with (fit/common/fit_termination.h) and a message saying so.
struct SolveOutcome {
  FitTermination termination = FitTermination::kFailure;
  std::string message;
};

SolveOutcome DescribeSolve(const ceres::Solver::Summary& summary) {
  switch (summary.termination_type) {
    case ceres::CONVERGENCE:
    case ceres::USER_SUCCESS:
      return {FitTermination::kConverged, "converged"};
    case ceres::NO_CONVERGENCE:
      return {
          FitTermination::kNoConvergence,
          "no convergence within " +
              std::to_string(std::max<int>(0, static_cast<int>(summary.iterations.size()) - 1)) +
              " iterations (the iteration limit): " + summary.message};
    case ceres::FAILURE:
    case ceres::USER_FAILURE:
      break;
  }
  return {FitTermination::kFailure, summary.message};
}

template <int N>
std::vector<double> Refine(int k, const Tetrahedron& tet, std::vector<double> b,
                           const std::vector<Vec>& points, const std::vector<Vec>& normals,
                           const PatchFitOptions& options, double loss_scale, bool guard,
                           SolveOutcome* outcome) {
  ceres::Problem problem;
  AddPointBlocks<PatchPointResidual<N>, N>(
      &problem, points.size(), !normals.empty(),
      [&](size_t i) {
        return MakePointResidual<N>(k, tet, points, normals, i, options.normal_weight);
      },
      loss_scale, b.data());
  if (guard) problem.AddResidualBlock(new ConvexityGuard(k, N, 1e-6), nullptr, b.data());
  if (!options.constraints.empty()) {
    Eigen::MatrixXd basis;
    std::string error;
    if (ShapeConstraintBasis(k, tet, options.constraints, &basis, &error))
      problem.SetManifold(b.data(), NewLinearSubspaceManifold(basis));
  }
  const ceres::Solver::Summary summary = SolvePatchProblem(&problem, options.max_iterations);
  if (outcome) *outcome = DescribeSolve(summary);
  return b;
}

std::vector<double> RefineAnyDegree(int k, const Tetrahedron& tet, const std::vector<double>& b,
                                    const std::vector<Vec>& points, const std::vector<Vec>& normals,
                                    const PatchFitOptions& options, double loss_scale, bool guard,
                                    SolveOutcome* outcome) {
  switch (k) {
    case 2:
      return Refine<10>(k, tet, b, points, normals, options, loss_scale, guard, outcome);
    case 3:
      return Refine<20>(k, tet, b, points, normals, options, loss_scale, guard, outcome);
    default:
      return Refine<35>(k, tet, b, points, normals, options, loss_scale, guard, outcome);
  }
}

// Degree-2 convex fit by the exact parameterisation, started from b (any quadric patch).
std::vector<double> ConvexQuadricFit(const Tetrahedron& tet, const std::vector<double>& b,
                                     const std::vector<Vec>& points,
                                     const std::vector<Vec>& normals,
                                     const PatchFitOptions& options, double loss_scale,
                                     SolveOutcome* outcome) {
  double scale = 0;
  for (double v : b) scale = std::max(scale, std::abs(v));
  const double margin = 1e-5 * scale;
  double a[6];
  GuoMatrix(2, b.data(), 0, 0, 0, a);
  Eigen::Matrix3d A;
  A << a[0], a[3], a[4], a[3], a[1], a[5], a[4], a[5], a[2];
  // Nearest positive definite start: clamp the eigenvalues at a few margins.
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(A);
  const Eigen::Vector3d lambda =
      eig.eigenvalues().cwiseMax(10 * margin + 1e-3 * eig.eigenvalues().cwiseAbs().maxCoeff());
  const Eigen::Matrix3d start =
      eig.eigenvectors() * lambda.asDiagonal() * eig.eigenvectors().transpose() -
      margin * Eigen::Matrix3d::Identity();
  const Eigen::Matrix3d L = start.llt().matrixL();
  std::vector<double> z = {L(0, 0), L(1, 0), L(1, 1), L(2, 0), L(2, 1),
                           L(2, 2), b[3],    b[6],    b[8],    b[9]};
  ceres::Problem problem;
  AddPointBlocks<ConvexQuadricPointResidual, 10>(
      &problem, points.size(), !normals.empty(),
      [&](size_t i) {
        return ConvexQuadricPointResidual{
            MakePointResidual<10>(2, tet, points, normals, i, options.normal_weight), margin};
      },
      loss_scale, z.data());
  *outcome = DescribeSolve(SolvePatchProblem(&problem, options.max_iterations));
  std::vector<double> out(10);
  ConvexQuadricControlPoints(z.data(), margin, out.data());
  return out;
}

}  // namespace

bool PatchFitOptions::IsValid(std::string* error) const {
  if (degree < 2 || degree > 4) {
    if (error) *error = "degree must be 2, 3 or 4 for fitting";
    return false;
  }
  if (!(normal_weight >= 0.0) || !std::isfinite(normal_weight)) {
    if (error) *error = "normal_weight must be a finite number >= 0";
    return false;
  }
  if (max_iterations < 1) {
    if (error) *error = "max_iterations must be >= 1";
    return false;
  }
  if (convex && !constraints.empty()) {
    if (error)
      *error =
          "shape constraints (through a vertex, a vertex normal, through an edge) cannot be "
          "combined with the convexity constraint";
    return false;
  }
  if (!constraints.empty()) {
    // Conflicts between the constraints themselves (shared control points) do not depend on
    // the tetrahedron; check them on the given one or the reference one.
    Eigen::MatrixXd basis;
    std::string why;
    if (!ShapeConstraintBasis(degree, has_tetrahedron ? tetrahedron : Tetrahedron(), constraints,
                              &basis, &why)) {
      if (error) *error = "shape constraints: " + why;
      return false;
    }
  }
  return true;
}

Model PatchFitResult::ToModel() const {
  Model m;
  m.AddBernsteinPatch(degree, tetrahedron, control_points);
  return m;
}

Tetrahedron EnclosingTetrahedron(const std::vector<Vec>& points) {
  Vec c = Vec::Zero();
  for (const Vec& p : points) c += p;
  c /= static_cast<double>(points.size());
  double R = 0;
  for (const Vec& p : points) R = std::max(R, (p - c).norm());
  if (!(R > 0)) R = 1.0;
  const double s = 3.0 * 1.1 * R / std::sqrt(3.0);
  return Tetrahedron(c + s * Vec(1, 1, 1), c + s * Vec(1, -1, -1), c + s * Vec(-1, 1, -1),
                     c + s * Vec(-1, -1, 1));
}

PatchFitResult FitBernsteinPatch(const std::vector<Vec>& points, const std::vector<Vec>& normals,
                                 const PatchFitOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  PatchFitResult result;
  result.points = points.size();
  result.degree = options.degree;
  result.convex_constraint = options.convex;
  std::string error;
  if (!options.IsValid(&error)) {
    result.message = error;
    return result;
  }
  const int k = options.degree;
  if (points.size() < static_cast<size_t>(NumBernsteinControlPoints(k))) {
    result.message = "too few points for a degree-" + std::to_string(k) +
                     " patch: " + std::to_string(points.size());
    return result;
  }
  result.degree = k;
  result.tetrahedron = options.has_tetrahedron ? options.tetrahedron : EnclosingTetrahedron(points);
  const Tetrahedron& tet = result.tetrahedron;
  Vec c = Vec::Zero();
  for (const Vec& p : points) c += p;
  c /= static_cast<double>(points.size());
  double R = 0;
  for (const Vec& p : points) R = std::max(R, (p - c).norm());
  const double h = 0.01 * R;

  // Unconstrained fit (also the reference for the cost of the constraint).
  std::vector<double> b = LinearInitialisation(k, tet, points, normals, h);
  if (!options.constraints.empty()) {
    // Start on the constraint subspace: the orthogonal projection N N^T b.
    Eigen::MatrixXd basis;
    std::string error;
    if (!ShapeConstraintBasis(k, tet, options.constraints, &basis, &error)) {
      result.message = "shape constraints: " + error;
      return result;
    }
    const Eigen::Map<const Eigen::VectorXd> bv(b.data(), static_cast<int>(b.size()));
    const Eigen::VectorXd projected = basis * (basis.transpose() * bv);
    b.assign(projected.data(), projected.data() + projected.size());
  }
  const double init_rms = Rms(k, tet, b, points, normals, nullptr);
  const double loss_scale = std::max(3.0 * init_rms, 1e-9 * R);
  SolveOutcome outcome;  // of the last solve
  std::vector<double> free_fit =
      RefineAnyDegree(k, tet, b, points, normals, options, loss_scale, false, &outcome);
  double angle;
  const double free_rms = Rms(k, tet, free_fit, points, normals, &angle);

  std::vector<double> fitted = free_fit;
  if (options.convex) {
    result.unconstrained_rms = free_rms;
    // Degree 2 first (exact parameterisation); degree >= 3 continues from it, elevated.
    std::vector<double> b2 = k == 2 ? free_fit : LinearInitialisation(2, tet, points, normals, h);
    std::vector<double> convex2 =
        ConvexQuadricFit(tet, b2, points, normals, options, loss_scale, &outcome);
    fitted = convex2;
    for (int d = 2; d < k; ++d) fitted = ElevateDegree(d, fitted);
    if (k >= 3)
      fitted =
          RefineAnyDegree(k, tet, fitted, points, normals, options, loss_scale, true, &outcome);
  }
  result.control_points = fitted;
  result.rms = Rms(k, tet, fitted, points, normals, &result.mean_normal_angle_deg,
                   &result.mean_normal_cosine);
  const ConvexityCertificate cert = CertifyConvexity(k, fitted.data());
  result.certified_convex = cert.convex;
  result.min_eigenvalue = cert.min_eigenvalue;
  result.termination = outcome.termination;
  if (outcome.termination == FitTermination::kFailure) {
    result.success = false;
    result.message = outcome.message;
  } else if (options.convex && !cert.convex) {
    result.success = false;
    result.message = "the convexity constraint could not be met (smallest A^mu eigenvalue " +
                     std::to_string(cert.min_eigenvalue) + ")";
  } else {
    result.success = true;
    result.message = outcome.message;
  }
  (void)angle;
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace implicitfit
