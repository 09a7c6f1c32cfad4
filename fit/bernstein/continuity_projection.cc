#include "fit/bernstein/continuity_projection.h"

#include <Eigen/CholmodSupport>
#include <Eigen/SPQRSupport>
#include <Eigen/SparseCore>
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "model/bernstein/bernstein_mesh_continuity.h"

namespace implicitfit {

namespace {
constexpr int kMaxMultiplierSteps = 100;
constexpr double kMultiplierPenalty = 1e8;  // mu x mean diag(Gh^T Gh) (header)
}  // namespace

// The projection in the domain-point unknowns (header): w = D^-1 P^T b, v = D^1/2 w, then
// v <- v - Gh^T y*, y* the least-squares solution of Gh^T y ~ v (twice; uniform grids), or the
// multiplier steps v <- (I + mu Gh^T Gh)^-1 v (refined grids); b = P D^-1/2 v.
struct ContinuityProjector::Factor {
  using SpqrMatrix = Eigen::SparseMatrix<double, Eigen::ColMajor, SuiteSparse_long>;
  SpqrMatrix Ght;  // (G D^-1/2)^T, G = C1 P; empty for continuity 0 and on refined grids
  Eigen::SPQR<SpqrMatrix> qr;  // uniform grids
  // Refined grids: Gh^T (ght, int indices) and the factor of I + mu Gh^T Gh.
  bool multipliers = false;
  Eigen::SparseMatrix<double> ght;
  double mu = 0;
  Eigen::CholmodSupernodalLLT<Eigen::SparseMatrix<double>> penalised;
  C0Parametrization c0;    // P, and the unknown every non-hanging control point equals
  Eigen::VectorXd copies;  // D: control points equal to each unknown
};

ContinuityProjector::ContinuityProjector(const BernsteinGrid& grid, int k, int continuity)
    : grid_(grid), k_(k), continuity_(continuity) {
  if (grid.NumTetrahedra() <= 1) return;
  factor_ = std::make_unique<Factor>();
  factor_->c0 = BernsteinC0Parametrization(grid, k);
  const long long nd = factor_->c0.unknowns;
  factor_->copies = Eigen::VectorXd::Zero(nd);
  for (long long i : factor_->c0.identity)
    if (i >= 0) factor_->copies[i] += 1.0;
  if (continuity == 0) return;
  const ContinuityRows c1 = BernsteinContinuityRows(grid, k, 1, 1);
  const Eigen::SparseMatrix<double, Eigen::RowMajor> G = c1.C * factor_->c0.P;
  std::vector<Eigen::Triplet<double, SuiteSparse_long>> ts;
  for (int r = 0; r < G.outerSize(); ++r)
    for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(G, r); it; ++it)
      ts.emplace_back(it.col(), r, it.value() / std::sqrt(factor_->copies[it.col()]));
  factor_->Ght.resize(nd, G.rows());
  factor_->Ght.setFromTriplets(ts.begin(), ts.end());
  if (grid.MaxLevel() == 0) {
    factor_->qr.compute(factor_->Ght);
    if (factor_->qr.info() != Eigen::Success)
      throw std::runtime_error("continuity projection: SuiteSparseQR failed");
    return;
  }
  factor_->multipliers = true;
  factor_->ght = Eigen::SparseMatrix<double>(factor_->Ght.cast<double>());
  factor_->Ght.resize(0, 0);  // the QR's copy is not needed here
  const Eigen::SparseMatrix<double> gram =
      factor_->ght * Eigen::SparseMatrix<double>(factor_->ght.transpose());
  factor_->mu = kMultiplierPenalty / std::max(gram.diagonal().mean(), 1e-300);
  Eigen::SparseMatrix<double> identity(nd, nd);
  identity.setIdentity();
  factor_->penalised.compute(identity + factor_->mu * gram);
  if (factor_->penalised.info() != Eigen::Success)
    throw std::runtime_error("continuity projection: CHOLMOD failed on I + mu Gh^T Gh");
}

ContinuityProjector::~ContinuityProjector() = default;

double ContinuityProjector::Project(std::vector<double>* b) const {
  const long long expected = grid_.NumTetrahedra() * NumBernsteinControlPoints(k_);
  if (static_cast<long long>(b->size()) != expected)
    throw std::invalid_argument("ProjectOntoContinuitySpace: wrong number of control points");
  if (!factor_) return 0.0;
  const Factor& f = *factor_;
  Eigen::VectorXd v = Eigen::VectorXd::Zero(f.copies.size());
  for (size_t i = 0; i < f.c0.identity.size(); ++i)
    if (f.c0.identity[i] >= 0) v[f.c0.identity[i]] += (*b)[i];
  v.array() /= f.copies.array().sqrt();  // D^1/2 w, w the mean of each unknown's copies
  if (continuity_ == 1 && f.multipliers) {
    // v - (I + mu M)^-1 v = (I + mu M)^-1 mu M v (M = Gh^T Gh): solving for the step, whose
    // right-hand side shrinks with the defect, keeps the solve's rounding relative to the step
    // instead of to v (solving for v itself moved a global quadric's control points by up to
    // 4.9e-5, test ProjectionKeepsAGlobalQuadricOnARefinedGrid).
    const double scale = std::max(v.cwiseAbs().maxCoeff(), 1e-300);
    for (int step = 0; step < kMaxMultiplierSteps; ++step) {
      const Eigen::VectorXd defect = f.ght.transpose() * v;
      if (defect.size() == 0 || defect.cwiseAbs().maxCoeff() <= 1e-15 * scale) break;
      v -= f.penalised.solve(f.mu * (f.ght * defect));
    }
  } else if (continuity_ == 1 && f.Ght.cols() > 0) {
    for (int pass = 0; pass < 2; ++pass) {
      const Eigen::VectorXd y = f.qr.solve(v);
      v -= f.Ght * y;
    }
  }
  v.array() /= f.copies.array().sqrt();  // w
  const Eigen::VectorXd projected = f.c0.P * v;
  std::copy(projected.data(), projected.data() + projected.size(), b->data());
  return ContinuityDefect(grid_, k_, continuity_, b->data());
}

double ProjectOntoContinuitySpace(const BernsteinGrid& grid, int k, int continuity,
                                  std::vector<double>* b) {
  return ContinuityProjector(grid, k, continuity).Project(b);
}

}  // namespace implicitfit
