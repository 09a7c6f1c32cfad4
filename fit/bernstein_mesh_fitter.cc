#include "fit/bernstein_mesh_fitter.h"

#include <ceres/ceres.h>

#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <memory>

#include "fit/continuity_projection.h"
#include "fit/patch_fitter.h"
#include "model/bernstein_conversion.h"
#include "model/bernstein_mesh_certificate.h"
#include "model/bernstein_mesh_continuity.h"
#include "model/convexity_certificate.h"

namespace implicitfit {
namespace {

using Vec = Eigen::Vector3d;
using SparseMatrix = Eigen::SparseMatrix<double>;

// B^k_lambda(tau) for every lambda, DESIGN.md order.
void BasisValues(int k, const double* tau, double* out) {
  static thread_local std::vector<double> unit;
  const long long n = NumBernsteinControlPoints(k);
  unit.assign(static_cast<size_t>(n), 0.0);
  for (long long j = 0; j < n; ++j) {
    unit[j] = 1.0;
    out[j] = BernsteinPatch::EvaluateBarycentric(k, unit.data(), tau);
    unit[j] = 0.0;
  }
}

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

// Step 1 (see the header). Returns b (not yet projected).
std::vector<double> LinearInitialisation(const BernsteinGrid& grid, int k, int continuity,
                                         const std::vector<Vec>& points,
                                         const std::vector<Vec>& normals, double d,
                                         const MeshFitOptions& options, const ContinuityRows& c2,
                                         const std::vector<bool>& c2_keep) {
  const long long n = NumBernsteinControlPoints(k);
  const std::vector<long long> domain = DomainPointIndices(grid, k);
  const long long nd = NumDomainPoints(grid, k);
  // Data rows in domain-point unknowns: sum_j B_j(tau) w[domain[t n + j]] = target.
  std::vector<Eigen::Triplet<double>> trip;
  std::vector<double> rhs;
  std::vector<double> basis(static_cast<size_t>(n));
  auto add_row = [&](const Vec& x, double target) {
    double tau[4];
    const long long t = grid.Locate(x.data(), tau);
    BasisValues(k, tau, basis.data());
    const long long row = static_cast<long long>(rhs.size());
    for (long long j = 0; j < n; ++j) trip.emplace_back(row, domain[t * n + j], basis[j]);
    rhs.push_back(target);
  };
  for (size_t i = 0; i < points.size(); ++i) {
    add_row(points[i], 0.0);
    add_row(points[i] + d * normals[i], d);
    add_row(points[i] - d * normals[i], -d);
  }
  SparseMatrix A(static_cast<long>(rhs.size()), nd);
  A.setFromTriplets(trip.begin(), trip.end());
  const Eigen::Map<const Eigen::VectorXd> y(rhs.data(), static_cast<long>(rhs.size()));
  // Selection P (control point -> domain point) to move rows of C onto w.
  SparseMatrix P(static_cast<long>(domain.size()), nd);
  {
    std::vector<Eigen::Triplet<double>> tp;
    for (size_t i = 0; i < domain.size(); ++i)
      tp.emplace_back(static_cast<long>(i), domain[i], 1.0);
    P.setFromTriplets(tp.begin(), tp.end());
  }
  SparseMatrix H = SparseMatrix(A.transpose()) * A;
  Eigen::VectorXd g = A.transpose() * y;
  if (continuity == 1) {
    const ContinuityRows c1 = BernsteinContinuityRows(grid, k, 1, 1);
    const SparseMatrix G = SparseMatrix(c1.C) * P;
    H += options.continuity_weight * options.continuity_weight * SparseMatrix(G.transpose()) * G;
  }
  // C2 smoothing: a weight per row relative to the data's scale (rows per non-empty tetrahedron).
  {
    std::vector<Eigen::Triplet<double>> ts;
    long long r = 0;
    for (int row = 0; row < c2.C.rows(); ++row) {
      if (!c2_keep[row]) continue;
      for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(c2.C, row); it; ++it)
        ts.emplace_back(r, it.col(), it.value());
      ++r;
    }
    SparseMatrix S(r, c2.C.cols());
    S.setFromTriplets(ts.begin(), ts.end());
    const SparseMatrix SP = S * P;
    H += options.smoothing_weight * options.smoothing_weight * SparseMatrix(SP.transpose()) * SP;
  }
  // A tiny ridge keeps the system definite where nothing else reaches (far corners).
  const double ridge = 1e-10 * std::max(1.0, H.diagonal().maxCoeff());
  for (long long i = 0; i < nd; ++i) H.coeffRef(i, i) += ridge;
  Eigen::SimplicialLDLT<SparseMatrix> solver(H);
  Eigen::VectorXd w = solver.solve(g);
  const Eigen::VectorXd b = P * w;
  return std::vector<double>(b.data(), b.data() + b.size());
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
    problem.AddResidualBlock(AnyPointCost(k, tets[t], points[i], normals[i], options.normal_weight),
                             loss.get(), base + t * n);
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
  if (degree < 2 || degree > 5) return fail("--degree must be 2..5 for a patch mesh");
  if (continuity != 0 && continuity != 1) return fail("--continuity must be 0 or 1");
  if (convex && continuity != 1)
    return fail(
        "--convex needs --continuity 1 (convex patches joined C0 can meet at a concave kink)");
  if (cells < 0 || cells > 200) return fail("--cells must be in 1..200");
  if (!(cell >= 0.0) || !std::isfinite(cell)) return fail("--cell must be a positive length");
  return true;
}

BernsteinGrid MeshGridForCloud(const std::vector<Vec>& points, int cells, double cell) {
  Vec lo = Vec::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  for (const Vec& p : points) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  Vec ext = hi - lo;
  const double longest = std::max(ext.maxCoeff(), 1e-12);
  for (int a = 0; a < 3; ++a) ext[a] = std::max(ext[a], 0.05 * longest) * 1.1;  // +5% each side
  const Vec center = 0.5 * (lo + hi);
  BernsteinGrid g;
  g.cell = cell > 0.0 ? cell : ext.maxCoeff() / (cells > 0 ? cells : 4);
  for (int a = 0; a < 3; ++a)
    g.cells[a] = std::max(1, static_cast<int>(std::ceil(ext[a] / g.cell - 1e-9)));
  g.origin = center - 0.5 * g.cell * Vec(g.cells[0], g.cells[1], g.cells[2]);
  return g;
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
  const int k = options.degree;
  const long long n = NumBernsteinControlPoints(k);
  result.degree = k;
  result.continuity = options.continuity;
  result.grid =
      options.has_grid ? options.grid : MeshGridForCloud(points, options.cells, options.cell);
  const BernsteinGrid& grid = result.grid;
  result.tetrahedra = grid.NumTetrahedra();
  const double diagonal = (grid.BoxMax() - grid.BoxMin()).norm();
  const double d = 0.01 * diagonal;

  const PointData data = LocatePoints(grid, points);
  const ContinuityRows c2 = BernsteinContinuityRows(grid, k, 2, 2);
  const std::vector<bool> c2_keep = EmptyFaceRows(c2, data);

  std::vector<double> b =
      LinearInitialisation(grid, k, options.continuity, points, normals, d, options, c2, c2_keep);
  ProjectOntoContinuitySpace(grid, k, options.continuity, &b);
  result.initial_rms = MeshRms(grid, k, b, points, normals, nullptr);
  const double loss_scale = std::max(3.0 * result.initial_rms, 1e-9 * diagonal);

  if (options.convex) {
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
    result.continuity_defect = ProjectOntoContinuitySpace(grid, k, options.continuity, &b);
  } else {
    // The refinement must not end worse than the (projected) initialisation it started from
    // (it can on real scans with inconsistent normals); keep the better of the two.
    const std::vector<double> initial = b;
    result.iterations = Refine(grid, k, options.continuity, points, normals, data, c2, c2_keep,
                               options, loss_scale, d, nullptr, &b);
    result.continuity_defect = ProjectOntoContinuitySpace(grid, k, options.continuity, &b);
    if (!(MeshRms(grid, k, b, points, normals, nullptr) <= result.initial_rms)) {
      b = initial;
      result.continuity_defect = ContinuityDefect(grid, k, options.continuity, b.data());
      result.kept_initialisation = true;
    }
  }
  result.control_points = b;
  result.rms = MeshRms(grid, k, b, points, normals, &result.mean_normal_angle_deg);
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
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace implicitfit
