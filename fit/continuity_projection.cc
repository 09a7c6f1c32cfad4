#include "fit/continuity_projection.h"

#include <Eigen/SPQRSupport>
#include <Eigen/SparseCore>
#include <stdexcept>

#include "model/bernstein_mesh_continuity.h"

namespace implicitfit {

double ProjectOntoContinuitySpace(const BernsteinGrid& grid, int k, int continuity,
                                  std::vector<double>* b) {
  const ContinuityRows rows = BernsteinContinuityRows(grid, k, 0, continuity);
  if (static_cast<long long>(b->size()) != rows.C.cols())
    throw std::invalid_argument("ProjectOntoContinuitySpace: wrong number of control points");
  if (rows.C.rows() == 0) return 0.0;
  using SpqrMatrix = Eigen::SparseMatrix<double, Eigen::ColMajor, SuiteSparse_long>;
  const SpqrMatrix Ct = SpqrMatrix(rows.C.transpose());
  Eigen::SPQR<SpqrMatrix> qr(Ct);
  if (qr.info() != Eigen::Success)
    throw std::runtime_error("continuity projection: SuiteSparseQR failed");
  Eigen::Map<Eigen::VectorXd> bv(b->data(), static_cast<Eigen::Index>(b->size()));
  for (int pass = 0; pass < 2; ++pass) {
    const Eigen::VectorXd y = qr.solve(bv);
    bv -= Ct * y;
  }
  return ContinuityDefect(grid, k, continuity, b->data());
}

}  // namespace implicitfit
