#include "fit/bernstein/continuity_projection.h"

#include <Eigen/SPQRSupport>
#include <Eigen/SparseCore>
#include <cmath>
#include <stdexcept>

#include "model/bernstein/bernstein_mesh_continuity.h"

namespace implicitfit {

// The projection in the domain-point unknowns (header): w = D^-1 P^T b, v = D^1/2 w, then
// v <- v - Gh^T y*, y* the least-squares solution of Gh^T y ~ v (twice), b = P D^-1/2 v.
struct ContinuityProjector::Factor {
  using SpqrMatrix = Eigen::SparseMatrix<double, Eigen::ColMajor, SuiteSparse_long>;
  SpqrMatrix Ght;  // (G D^-1/2)^T, G = C1 P; empty for continuity 0
  Eigen::SPQR<SpqrMatrix> qr;
  std::vector<long long> domain;  // P: the domain point of every control point
  Eigen::VectorXd copies;         // D: control points per domain point
};

ContinuityProjector::ContinuityProjector(const BernsteinGrid& grid, int k, int continuity)
    : grid_(grid), k_(k), continuity_(continuity) {
  if (grid.NumTetrahedra() <= 1) return;
  factor_ = std::make_unique<Factor>();
  factor_->domain = DomainPointIndices(grid, k);
  const long long nd = NumDomainPoints(grid, k);
  factor_->copies = Eigen::VectorXd::Zero(nd);
  for (long long i : factor_->domain) factor_->copies[i] += 1.0;
  if (continuity == 0) return;
  const ContinuityRows c1 = BernsteinContinuityRows(grid, k, 1, 1);
  std::vector<Eigen::Triplet<double, SuiteSparse_long>> ts;
  for (int r = 0; r < c1.C.rows(); ++r)
    for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(c1.C, r); it; ++it) {
      const long long w = factor_->domain[it.col()];
      ts.emplace_back(w, r, it.value() / std::sqrt(factor_->copies[w]));
    }
  factor_->Ght.resize(nd, c1.C.rows());
  factor_->Ght.setFromTriplets(ts.begin(), ts.end());  // duplicates (same w, same row) summed
  factor_->qr.compute(factor_->Ght);
  if (factor_->qr.info() != Eigen::Success)
    throw std::runtime_error("continuity projection: SuiteSparseQR failed");
}

ContinuityProjector::~ContinuityProjector() = default;

double ContinuityProjector::Project(std::vector<double>* b) const {
  const long long expected = grid_.NumTetrahedra() * NumBernsteinControlPoints(k_);
  if (static_cast<long long>(b->size()) != expected)
    throw std::invalid_argument("ProjectOntoContinuitySpace: wrong number of control points");
  if (!factor_) return 0.0;
  const Factor& f = *factor_;
  Eigen::VectorXd v = Eigen::VectorXd::Zero(f.copies.size());
  for (size_t i = 0; i < f.domain.size(); ++i) v[f.domain[i]] += (*b)[i];
  v.array() /= f.copies.array().sqrt();  // D^1/2 (D^-1 P^T b)
  if (continuity_ == 1)
    for (int pass = 0; pass < 2; ++pass) {
      const Eigen::VectorXd y = f.qr.solve(v);
      v -= f.Ght * y;
    }
  v.array() /= f.copies.array().sqrt();  // w
  for (size_t i = 0; i < f.domain.size(); ++i) (*b)[i] = v[f.domain[i]];
  return ContinuityDefect(grid_, k_, continuity_, b->data());
}

double ProjectOntoContinuitySpace(const BernsteinGrid& grid, int k, int continuity,
                                  std::vector<double>* b) {
  return ContinuityProjector(grid, k, continuity).Project(b);
}

}  // namespace implicitfit
