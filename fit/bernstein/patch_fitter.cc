#include "fit/bernstein/patch_fitter.h"

#include <ceres/ceres.h>

#include <Eigen/Dense>
#include <algorithm>
#include <chrono>
#include <cmath>

#include "fit/bernstein/convex_patch_fit.h"
#include "fit/bernstein/patch_residuals.h"
#include "model/bernstein/bernstein_conversion.h"
#include "model/certificates/convexity_certificate.h"

namespace implicitfit {
namespace {

using Vec = Eigen::Vector3d;

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

template <int N>
std::vector<double> Refine(int k, const Tetrahedron& tet, std::vector<double> b,
                           const std::vector<Vec>& points, const std::vector<Vec>& normals,
                           const PatchFitOptions& options, double loss_scale,
                           SolveOutcome* outcome) {
  ceres::Problem problem;
  AddPointBlocks<PatchPointResidual<N>, N>(
      &problem, points.size(), !normals.empty(),
      [&](size_t i) {
        return MakePointResidual<N>(k, tet, points, normals, i, options.normal_weight);
      },
      loss_scale, b.data());
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
                                    const PatchFitOptions& options, double loss_scale,
                                    SolveOutcome* outcome) {
  switch (k) {
    case 2:
      return Refine<10>(k, tet, b, points, normals, options, loss_scale, outcome);
    case 3:
      return Refine<20>(k, tet, b, points, normals, options, loss_scale, outcome);
    default:
      return Refine<35>(k, tet, b, points, normals, options, loss_scale, outcome);
  }
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
  if (convex && !constraints.through_edges.empty()) {
    if (error)
      *error =
          "a convex patch cannot pass through an edge of its tetrahedron (f = 0 along the edge "
          "makes its second derivative there 0, so no A^mu can be positive definite)";
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
  const double init_rms = PatchRms(k, tet, b, points, normals, nullptr);
  const double loss_scale = std::max(3.0 * init_rms, 1e-9 * R);
  SolveOutcome outcome;  // of the last solve
  std::vector<double> free_fit =
      RefineAnyDegree(k, tet, b, points, normals, options, loss_scale, &outcome);
  const double free_rms = PatchRms(k, tet, free_fit, points, normals, nullptr);

  std::vector<double> fitted = free_fit;
  if (options.convex) {
    result.unconstrained_rms = free_rms;
    // The unconstrained degree-2 fit is the source of the convex starts
    // (fit/bernstein/convex_patch_fit.h); with shape constraints, the fit without them.
    PatchFitOptions free2_options = options;
    free2_options.constraints = PatchShapeConstraints();
    std::vector<double> free2 = k == 2 && options.constraints.empty() ? free_fit : std::vector<double>();
    if (free2.empty()) {
      SolveOutcome ignored;
      free2 = RefineAnyDegree(2, tet, LinearInitialisation(2, tet, points, normals, h), points,
                              normals, free2_options, loss_scale, &ignored);
    }
    ConvexPatchProblem problem;
    problem.degree = k;
    problem.tetrahedron = tet;
    problem.points = &points;
    problem.normals = &normals;
    problem.normal_weight = options.normal_weight;
    problem.max_iterations = options.max_iterations;
    problem.free_loss_scale = loss_scale;
    if (!options.constraints.empty()) {
      std::string why;
      ShapeConstraintBasis(k, tet, options.constraints, &problem.subspace, &why);
    }
    const ConvexPatchFit convex = FitConvexPatch(problem, free2);
    result.convex_start = convex.start;
    result.relative_margin = convex.relative_margin;
    if (!convex.success) {
      result.message = "the convexity constraint could not be met: " + convex.message;
      result.seconds =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      return result;
    }
    fitted = convex.control_points;
    outcome = convex.outcome;
  }
  result.control_points = fitted;
  result.rms = PatchRms(k, tet, fitted, points, normals, &result.mean_normal_angle_deg,
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
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace implicitfit
