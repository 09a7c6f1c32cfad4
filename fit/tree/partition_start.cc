#include "fit/tree/partition_start.h"

#include <Eigen/Dense>
#include <Eigen/Sparse>
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "model/bernstein/bernstein_conversion.h"

namespace implicitfit {
namespace {

using Vec = Eigen::Vector3d;

// The child's linear basis phi(u) at the normalised point u: plane a . u - d, quadric
// u^T A u + 2 b . u + c in the coefficient order of model/primitives/quadric.h.
int BasisSize(bool quadric) { return quadric ? 10 : 4; }
void Basis(bool quadric, const Vec& u, double* phi) {
  if (!quadric) {
    phi[0] = u.x(), phi[1] = u.y(), phi[2] = u.z(), phi[3] = -1.0;
    return;
  }
  phi[0] = u.x() * u.x(), phi[1] = u.y() * u.y(), phi[2] = u.z() * u.z();
  phi[3] = 2 * u.x() * u.y(), phi[4] = 2 * u.x() * u.z(), phi[5] = 2 * u.y() * u.z();
  phi[6] = 2 * u.x(), phi[7] = 2 * u.y(), phi[8] = 2 * u.z(), phi[9] = 1.0;
}

// World-coordinate node parameters from the coefficients theta in u = (x - c) / s.
std::vector<double> WorldChild(bool quadric, const double* theta, const Vec& c, double s) {
  if (!quadric) {
    const Vec a = Vec(theta[0], theta[1], theta[2]) / s;
    const double d = a.dot(c) + theta[3], n = a.norm();
    if (!(n > 0)) return {};
    return {a.x() / n, a.y() / n, a.z() / n, d / n};
  }
  Eigen::Matrix3d A;
  A << theta[0], theta[3], theta[4], theta[3], theta[1], theta[5], theta[4], theta[5], theta[2];
  const Vec b(theta[6], theta[7], theta[8]);
  const Eigen::Matrix3d Aw = A / (s * s);
  const Vec bw = -A * c / (s * s) + b / s;
  const double cw = c.dot(A * c) / (s * s) - 2 * b.dot(c) / s + theta[9];
  std::vector<double> q = {Aw(0, 0), Aw(1, 1), Aw(2, 2), Aw(0, 1), Aw(0, 2),
                           Aw(1, 2), bw.x(),   bw.y(),   bw.z(),   cw};
  double largest = 0;
  for (double v : q) largest = std::max(largest, std::abs(v));
  if (!(largest > 0) || !std::isfinite(largest)) return {};
  for (double& v : q) v /= largest;
  return q;
}

// quadric-patch child: the world polynomial of theta, NOT normalised (a patch's value is its
// polynomial, so the children keep the linear start's common scale f ~ distance / s), as
// degree-2 control points on the tetrahedron with vertices lo, lo + 3 d_k e_k (k = 1..3),
// which holds the box [lo, lo + d] (x/dx + y/dy + z/dz <= 3 there).
std::vector<double> WorldPatch(const double* theta, const Vec& c, double s, const Vec& lo,
                               const Vec& d, Tetrahedron* tet) {
  Eigen::Matrix3d A;
  A << theta[0], theta[3], theta[4], theta[3], theta[1], theta[5], theta[4], theta[5], theta[2];
  const Vec b(theta[6], theta[7], theta[8]);
  CartesianQuadric q;
  q.A = A / (s * s);
  q.b = -A * c / (s * s) + b / s;
  q.c = c.dot(A * c) / (s * s) - 2 * b.dot(c) / s + theta[9];
  *tet = Tetrahedron(lo + 3 * d.x() * Vec::UnitX(), lo + 3 * d.y() * Vec::UnitY(),
                     lo + 3 * d.z() * Vec::UnitZ(), lo);
  std::vector<double> control = QuadricToBernstein(q, *tet, 2);
  for (double v : control)
    if (!std::isfinite(v)) return {};
  return control;
}

}  // namespace

bool IsPartitionChildKind(const std::string& child) {
  return child == "plane" || child == "quadric" || child == "quadric-patch";
}

PartitionStart LinearPartitionStart(const std::vector<Vec>& points, const std::vector<Vec>& normals,
                                    const PartitionStartOptions& options) {
  if (!IsPartitionChildKind(options.child))
    throw std::invalid_argument(
        "the partition child must be plane, quadric or quadric-patch, not '" + options.child + "'");
  for (int k = 0; k < 3; ++k)
    if (options.cells[k] < 1) throw std::invalid_argument("every grid count must be >= 1");
  if (!(options.epsilon_fraction > 0 && options.epsilon_fraction <= 0.5))
    throw std::invalid_argument("epsilon fraction must be in (0, 0.5]");
  PartitionStart out;
  if (points.empty() || normals.size() != points.size()) {
    out.message = "the partition start needs points with normals";
    return out;
  }
  const bool patch = options.child == "quadric-patch";
  const bool quadric = options.child == "quadric" || patch;
  Vec lo = points[0], hi = points[0];
  for (const Vec& p : points) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  if (options.has_box) {
    lo = options.box_min;
    hi = options.box_max;
    if (!((hi - lo).array() > 0).all()) throw std::invalid_argument("the box must have volume");
  } else {
    const Vec margin = 0.05 * (hi - lo).cwiseMax(Vec::Constant(1e-9 * (hi - lo).norm() + 1e-12));
    lo -= margin;
    hi += margin;
  }
  std::vector<std::vector<double>> cuts(3);
  double width = 1e308;
  for (int k = 0; k < 3; ++k) {
    const double step = (hi[k] - lo[k]) / options.cells[k];
    for (int i = 1; i < options.cells[k]; ++i) cuts[k].push_back(lo[k] + i * step);
    if (options.cells[k] > 1) width = std::min(width, step);
  }
  if (width > 1e307) width = (hi - lo).minCoeff();
  const double eps = options.epsilon_fraction * width;
  const Vec centre = 0.5 * (lo + hi);
  const double s = 0.5 * (hi - lo).norm();
  const double h = 0.01 * (hi - lo).norm();

  const int kb = BasisSize(quadric);
  const int nx = options.cells[0], ny = options.cells[1], nz = options.cells[2];
  const int num_cells = nx * ny * nz, K = num_cells * kb;
  const UnitStep& mu = UnitStep::OfOrder(options.order);

  // Rows: (point, offset) with target offset / s, in normalised units.
  std::vector<Eigen::Triplet<double>> triplets, global_triplets;
  std::vector<double> rhs;
  int row = 0;
  double phi[10];
  for (size_t i = 0; i < points.size(); ++i) {
    const Vec n = normals[i].normalized();
    if (!n.allFinite()) continue;
    for (double t : {0.0, h, -h}) {
      const Vec x = points[i] + t * n;
      int cells[3][PartitionAxis::kMaxCells];
      double factors[3][PartitionAxis::kMaxCells];
      int counts[3];
      for (int k = 0; k < 3; ++k)
        counts[k] = PartitionAxis::Factors(cuts[k], x[k], eps, mu, cells[k], factors[k]);
      Basis(quadric, (x - centre) / s, phi);
      for (int c = 0; c < counts[2]; ++c)
        for (int b = 0; b < counts[1]; ++b)
          for (int a = 0; a < counts[0]; ++a) {
            const double w = factors[0][a] * factors[1][b] * factors[2][c];
            const int cell = cells[0][a] + nx * (cells[1][b] + ny * cells[2][c]);
            for (int j = 0; j < kb; ++j) triplets.emplace_back(row, cell * kb + j, w * phi[j]);
          }
      for (int j = 0; j < kb; ++j) global_triplets.emplace_back(row, j, phi[j]);
      rhs.push_back(t / s);
      ++row;
    }
  }
  if (row < 3 * kb) {
    out.message = "too few oriented points for the partition start";
    return out;
  }
  const Eigen::Map<const Eigen::VectorXd> y(rhs.data(), row);

  // The global child: the same rows with one cell.
  Eigen::SparseMatrix<double> G(row, kb);
  G.setFromTriplets(global_triplets.begin(), global_triplets.end());
  Eigen::MatrixXd GtG = Eigen::MatrixXd(G.transpose() * G);
  GtG.diagonal().array() += 1e-9 * GtG.trace() / kb;
  const Eigen::VectorXd global = GtG.ldlt().solve(G.transpose() * y);

  Eigen::SparseMatrix<double> A(row, K);
  A.setFromTriplets(triplets.begin(), triplets.end());
  Eigen::SparseMatrix<double> AtA = A.transpose() * A;
  double trace = 0;
  for (int j = 0; j < K; ++j) trace += AtA.coeff(j, j);
  const double lambda = 1e-6 * trace / K;
  Eigen::VectorXd b = A.transpose() * y;
  for (int c = 0; c < num_cells; ++c)
    for (int j = 0; j < kb; ++j) {
      AtA.coeffRef(c * kb + j, c * kb + j) += lambda;
      b[c * kb + j] += lambda * global[j];
    }
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt(AtA);
  if (ldlt.info() != Eigen::Success) {
    out.message = "the linear system of the partition start is singular";
    return out;
  }
  const Eigen::VectorXd theta = ldlt.solve(b);
  out.linear_rms = s * std::sqrt((A * theta - y).squaredNorm() / row);

  Model& m = out.model;
  std::vector<int> children;
  for (int c = 0; c < num_cells; ++c) {
    if (patch) {  // the cell grown by eps on every side (its blend zone), in a tetrahedron
      const Vec step = (hi - lo).cwiseQuotient(Vec(nx, ny, nz));
      const Vec index(c % nx, (c / nx) % ny, c / (nx * ny));
      const Vec cell_lo = lo + index.cwiseProduct(step) - Vec::Constant(eps);
      Tetrahedron tet;
      std::vector<double> control = WorldPatch(theta.data() + c * kb, centre, s, cell_lo,
                                               step + Vec::Constant(2 * eps), &tet);
      if (control.empty()) {
        out.message = "the partition start found a degenerate child";
        return out;
      }
      children.push_back(m.AddBernsteinPatch(2, tet, control));
      continue;
    }
    std::vector<double> p = WorldChild(quadric, theta.data() + c * kb, centre, s);
    if (p.empty()) p = WorldChild(quadric, global.data(), centre, s);
    if (p.empty()) {
      out.message = "the partition start found a degenerate child";
      return out;
    }
    children.push_back(m.AddPrimitive(quadric ? NodeType::kQuadric : NodeType::kPlane, p));
  }
  m.AddPartition(cuts, eps, options.order, children);
  out.success = true;
  out.message = "linear start";
  return out;
}

}  // namespace implicitfit
