#include "fit/bernstein/convex_patch_fit.h"

#include <ceres/manifold.h>
#include <ceres/sphere_manifold.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>

#include "fit/bernstein/convex_feasible_start.h"
#include "model/bernstein/bernstein_conversion.h"
#include "model/certificates/convexity_certificate.h"

namespace implicitfit {
namespace {

using Vec = Eigen::Vector3d;

constexpr double kQuadricMargin = 1e-5;      // m of A = L L^T + m I, |z| = 1 (see the header)
constexpr double kElevatedMargin = 1e-4;     // the same for a degree-2 start of degree 3, 4
constexpr int kScreeningIterations = 30;     // per start, before the best one continues

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
  // design order: 2000 1100 1010 1001 0200 0110 0101 0020 0011 0002
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

Eigen::Matrix3d GuoA(const std::vector<double>& b) {
  double a[6];
  GuoMatrix(2, b.data(), 0, 0, 0, a);
  Eigen::Matrix3d A;
  A << a[0], a[3], a[4], a[3], a[1], a[5], a[4], a[5], a[2];
  return A;
}

// z on the unit sphere for a degree-2 patch b with Guo matrix A > 0, up to the positive scale
// s of b that |z(s)| = 1 needs: |z(s)|^2 = tr(s A - m I) + s^2 (|b4|^2 + b44^2). The
// eigenvalues of s A below 2 m are raised to 2 m (a change of at most 2e-5 of |z|).
std::vector<double> UnitZ(const std::vector<double>& b, double m) {
  Eigen::Matrix3d A = GuoA(b);
  const double lin2 = b[3] * b[3] + b[6] * b[6] + b[8] * b[8] + b[9] * b[9];
  double s = 1.0;
  for (int pass = 0; pass < 3; ++pass) {
    const double tr = A.trace();
    s = lin2 > 0 ? (-tr + std::sqrt(tr * tr + 4 * lin2 * (1 + 3 * m))) / (2 * lin2)
                 : (1 + 3 * m) / tr;
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(s * A);
    const Eigen::Vector3d lambda = eig.eigenvalues().cwiseMax(2 * m);
    A = eig.eigenvectors() * lambda.asDiagonal() * eig.eigenvectors().transpose() / s;
  }
  const Eigen::Matrix3d L = (s * A - m * Eigen::Matrix3d::Identity()).llt().matrixL();
  return {L(0, 0), L(1, 0), L(1, 1), L(2, 0), L(2, 1), L(2, 2),
          s * b[3], s * b[6], s * b[8], s * b[9]};
}

// Starts of the degree-2 fit (see the header), all certified convex.
struct Start {
  std::string name;
  std::vector<double> b;
};

std::vector<double> ClampedCartesian(const CartesianQuadric& q0, const Tetrahedron& tet,
                                     double floor) {
  CartesianQuadric q = q0;
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(q.A);
  const Eigen::Vector3d lambda = eig.eigenvalues().cwiseMax(floor);
  q.A = eig.eigenvectors() * lambda.asDiagonal() * eig.eigenvectors().transpose();
  return QuadricToBernstein(q, tet, 2);
}

std::vector<Start> QuadricStarts(const ConvexPatchProblem& p, const std::vector<double>& free2) {
  const std::vector<Vec>& x = *p.points;
  Vec c = Vec::Zero();
  for (const Vec& v : x) c += v;
  c /= static_cast<double>(x.size());
  double R = 0;
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
  for (const Vec& v : x) {
    R = std::max(R, (v - c).norm());
    cov += (v - c) * (v - c).transpose();
  }
  if (!(R > 0)) R = 1.0;
  std::vector<Start> starts;
  // plane: n . (x - c) + (kappa / 2) |x - c|^2, kappa = 1e-3 / R, n oriented by the normals.
  Vec n = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(cov).eigenvectors().col(0);
  if (!p.normals->empty()) {
    double agree = 0;
    for (const Vec& m : *p.normals) agree += m.dot(n);
    if (agree < 0) n = -n;
  }
  const double kappa = 1e-3 / R;
  CartesianQuadric plane;
  plane.A = 0.5 * kappa * Eigen::Matrix3d::Identity();
  plane.b = 0.5 * (n - kappa * c);
  plane.c = -n.dot(c) + 0.5 * kappa * c.squaredNorm();
  starts.push_back({"plane", QuadricToBernstein(plane, p.tetrahedron, 2)});
  // project: the unconstrained fit's Cartesian Hessian with its eigenvalues clamped.
  const CartesianQuadric q = BernsteinToQuadric(free2.data(), p.tetrahedron);
  const double top = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(q.A)
                         .eigenvalues()
                         .cwiseAbs()
                         .maxCoeff();
  starts.push_back({"project", ClampedCartesian(q, p.tetrahedron, 1e-3 * top + 1e-300)});
  // clamp: Guo's A in barycentric coordinates clamped the same way (the start used before).
  {
    const Eigen::Matrix3d A = GuoA(free2);
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(A);
    const double big = eig.eigenvalues().cwiseAbs().maxCoeff();
    const Eigen::Vector3d lambda = eig.eigenvalues().cwiseMax(1e-3 * big + 1e-300);
    const Eigen::Matrix3d Ac = eig.eigenvectors() * lambda.asDiagonal() * eig.eigenvectors().transpose();
    std::vector<double> b = free2;
    const int pair[3][3] = {{0, 1, 2}, {1, 4, 5}, {2, 5, 7}};
    const int four[3] = {3, 6, 8};
    for (int i = 0; i < 3; ++i)
      for (int j = i; j < 3; ++j) b[pair[i][j]] = Ac(i, j) - b[9] + b[four[i]] + b[four[j]];
    starts.push_back({"clamp", b});
  }
  return starts;
}

struct Candidate {
  std::vector<double> z;  // degree-2 parameters, or control points for the guarded fits
  double cost = std::numeric_limits<double>::infinity();
  SolveOutcome outcome;
  int iterations = 0;
};

// One degree-2 exact-parameterisation solve from z, `iterations` at most.
Candidate SolveQuadric(const ConvexPatchProblem& p, std::vector<double> z, double margin,
                       double loss_scale, int iterations) {
  ceres::Problem problem;
  AddPointBlocks<ConvexQuadricPointResidual, 10>(
      &problem, p.points->size(), !p.normals->empty(),
      [&](size_t i) {
        return ConvexQuadricPointResidual{
            MakePointResidual<10>(2, p.tetrahedron, *p.points, *p.normals, i, p.normal_weight),
            margin};
      },
      loss_scale, z.data());
  problem.SetManifold(z.data(), new ceres::SphereManifold<10>());
  const ceres::Solver::Summary summary = SolvePatchProblem(&problem, iterations);
  Candidate c;
  c.outcome = DescribeSolve(summary);
  c.cost = summary.final_cost;
  c.iterations = static_cast<int>(summary.iterations.size()) - 1;
  c.z = z;
  return c;
}

std::vector<double> QuadricOf(const std::vector<double>& z, double margin) {
  std::vector<double> b(10);
  ConvexQuadricControlPoints(z.data(), margin, b.data());
  return b;
}

// The unit sphere within the subspace span(N) (N orthonormal columns; N = I: the whole sphere):
// x = N y with |y| = 1; tangent vectors are N B d with B an orthonormal basis of y's complement.
class UnitSubspaceManifold : public ceres::Manifold {
 public:
  explicit UnitSubspaceManifold(Eigen::MatrixXd basis) : n_(std::move(basis)) {}
  int AmbientSize() const override { return static_cast<int>(n_.rows()); }
  int TangentSize() const override { return static_cast<int>(n_.cols()) - 1; }
  bool Plus(const double* x, const double* delta, double* out) const override {
    const Eigen::VectorXd y = Coordinates(x);
    const Eigen::VectorXd v =
        y + Complement(y) * Eigen::Map<const Eigen::VectorXd>(delta, TangentSize());
    Eigen::Map<Eigen::VectorXd>(out, AmbientSize()) = n_ * v.normalized();
    return true;
  }
  bool PlusJacobian(const double* x, double* jacobian) const override {
    Eigen::Map<Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>(
        jacobian, AmbientSize(), TangentSize()) = n_ * Complement(Coordinates(x));
    return true;
  }
  bool Minus(const double* y, const double* x, double* out) const override {
    const Eigen::VectorXd yx = Coordinates(x), yy = n_.transpose() * Eigen::Map<const Eigen::VectorXd>(y, AmbientSize());
    Eigen::Map<Eigen::VectorXd>(out, TangentSize()) = Complement(yx).transpose() * yy / yy.dot(yx);
    return true;
  }
  bool MinusJacobian(const double* x, double* jacobian) const override {
    Eigen::Map<Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>(
        jacobian, TangentSize(), AmbientSize()) = Complement(Coordinates(x)).transpose() * n_.transpose();
    return true;
  }

 private:
  Eigen::VectorXd Coordinates(const double* x) const {
    return (n_.transpose() * Eigen::Map<const Eigen::VectorXd>(x, AmbientSize())).normalized();
  }
  // Columns 2..m of the Householder reflection that maps y to +-e_1: orthonormal, orthogonal to y.
  static Eigen::MatrixXd Complement(const Eigen::VectorXd& y) {
    const int m = static_cast<int>(y.size());
    Eigen::VectorXd v = y;
    v[0] += y[0] >= 0 ? 1.0 : -1.0;
    const Eigen::MatrixXd H =
        Eigen::MatrixXd::Identity(m, m) - 2.0 * v * v.transpose() / v.squaredNorm();
    return H.rightCols(m - 1);
  }
  Eigen::MatrixXd n_;
};

// Returns false (step rejected) when some A^mu misses the relative margin.
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
    const std::vector<double> b(p[0], p[0] + n);
    return CertifiedRelativeMargin(degree, b) >= relative_margin;
  }
};

template <int N>
Candidate SolveGuarded(const ConvexPatchProblem& p, std::vector<double> b, double loss_scale,
                       const Eigen::MatrixXd& subspace) {
  // Scale normalised: b on the unit sphere of its subspace.
  Eigen::Map<Eigen::VectorXd>(b.data(), N).normalize();
  ceres::Problem problem;
  AddPointBlocks<PatchPointResidual<N>, N>(
      &problem, p.points->size(), !p.normals->empty(),
      [&](size_t i) {
        return MakePointResidual<N>(p.degree, p.tetrahedron, *p.points, *p.normals, i,
                                    p.normal_weight);
      },
      loss_scale, b.data());
  // Guard with twice the required margin, so the written (rounded) patch keeps the stated one.
  problem.AddResidualBlock(new ConvexityGuard(p.degree, N, 2 * kConvexRelativeMargin), nullptr,
                           b.data());
  problem.SetManifold(b.data(), new UnitSubspaceManifold(
                                    subspace.size() ? subspace : Eigen::MatrixXd::Identity(N, N)));
  const ceres::Solver::Summary summary = SolvePatchProblem(&problem, p.max_iterations);
  Candidate c;
  c.outcome = DescribeSolve(summary);
  c.cost = summary.final_cost;
  c.z = b;
  return c;
}

Candidate SolveGuardedAnyDegree(const ConvexPatchProblem& p, const std::vector<double>& b,
                                double loss_scale) {
  switch (p.degree) {
    case 2:
      return SolveGuarded<10>(p, b, loss_scale, p.subspace);
    case 3:
      return SolveGuarded<20>(p, b, loss_scale, p.subspace);
    default:
      return SolveGuarded<35>(p, b, loss_scale, p.subspace);
  }
}

}  // namespace

double CertifiedRelativeMargin(int k, const std::vector<double>& b) {
  const ConvexityCertificate c = CertifyConvexity(k, b.data());
  if (!c.convex) return -std::numeric_limits<double>::infinity();
  double scale = 0;
  for (double v : b) scale = std::max(scale, std::abs(v));
  return scale > 0 ? c.min_eigenvalue / scale : -std::numeric_limits<double>::infinity();
}

ConvexPatchFit FitConvexPatch(const ConvexPatchProblem& p, const std::vector<double>& free2) {
  ConvexPatchFit fit;
  const bool final_quadric = p.degree == 2 && p.subspace.size() == 0;
  const double m = final_quadric ? kQuadricMargin : kElevatedMargin;
  // The degree-2 starts, the loss scale from the best of them, a short solve from each, the
  // lowest cost continued to the end.
  const std::vector<Start> starts = QuadricStarts(p, free2);
  double best_rms = std::numeric_limits<double>::infinity();
  for (const Start& s : starts)
    best_rms = std::min(best_rms, PatchRms(2, p.tetrahedron, s.b, *p.points, *p.normals, nullptr));
  fit.loss_scale = std::max(3.0 * best_rms, p.free_loss_scale);
  Candidate best;
  for (const Start& s : starts) {
    ++fit.starts;
    Candidate c = SolveQuadric(p, UnitZ(s.b, m), m, fit.loss_scale,
                               std::min(kScreeningIterations, p.max_iterations));
    if (c.outcome.termination != FitTermination::kFailure && c.cost < best.cost) {
      best = c;
      fit.start = s.name;
    }
  }
  if (!std::isfinite(best.cost)) {
    fit.message = "every convex start failed: " + best.outcome.message;
    return fit;
  }
  if (best.outcome.termination == FitTermination::kNoConvergence &&
      p.max_iterations > kScreeningIterations) {
    Candidate more = SolveQuadric(p, best.z, m, fit.loss_scale, p.max_iterations - kScreeningIterations);
    if (more.outcome.termination != FitTermination::kFailure) best = more;
  }
  fit.outcome = best.outcome;
  std::vector<double> b = QuadricOf(best.z, m);
  if (!final_quadric) {
    for (int d = 2; d < p.degree; ++d) b = ElevateDegree(d, b);
    if (p.subspace.size()) {
      std::string why;
      std::vector<double> on;
      if (!ConvexStartOnSubspace(p.degree, b, p.subspace, 4 * kConvexRelativeMargin, &on, &why)) {
        fit.message = why;
        return fit;
      }
      b = on;
    }
    const Candidate g = SolveGuardedAnyDegree(p, b, fit.loss_scale);
    fit.outcome = g.outcome;
    if (g.outcome.termination == FitTermination::kFailure) {
      fit.message = g.outcome.message;
      return fit;
    }
    b = g.z;
  }
  fit.control_points = b;
  fit.relative_margin = CertifiedRelativeMargin(p.degree, b);
  if (!(fit.relative_margin >= kConvexRelativeMargin)) {
    fit.message = "the convexity margin could not be met (lambda_min / max |b| = " +
                  std::to_string(fit.relative_margin) + ")";
    return fit;
  }
  fit.success = true;
  fit.message = fit.outcome.message;
  return fit;
}

}  // namespace implicitfit
