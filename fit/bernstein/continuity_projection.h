// Exact projection of a Bernstein mesh's control points onto its continuity space ker C
// (model/bernstein/bernstein_mesh_continuity.h: C0 rows, plus C1 rows for continuity 1).
//
// Maths. The orthogonal projection of b onto ker C is the least-squares residual of
// C^T y ~ b: b - C^T y* is orthogonal to range(C^T) = (ker C)^perp, whatever least-squares
// solution y* is taken (C has redundant rows, so y* is not unique but the residual is).
// y* comes from SuiteSparseQR (rank-revealing sparse QR, through Eigen's SPQR module), so the
// redundant rows are detected instead of making the system singular. One refinement pass
// (the same projection applied to the result) removes the rounding of the first.
// Computed in the domain points (model/bernstein/bernstein_mesh_continuity.h): ker C0 = range P (b = P w,
// P the 0/1 map from the global domain points to every tetrahedron's control points) and
// ker C = P ker G (G = C1 P) lies inside it, so the projection onto ker C is the projection
// onto range P (w = D^-1 P^T b, the mean of each domain point's copies, D = P^T P their count)
// followed by the projection onto ker G in the metric of D (|P w|^2 = w^T D w), i.e. the
// Euclidean one onto ker(G D^-1/2) in v = D^1/2 w, by the QR of (G D^-1/2)^T. Same result as the
// QR of C^T, on about a third of the unknowns and without the C0 rows (kitten, degree 4:
// 20 625 domain points against 60 480 control points); C0 needs no QR at all.
// ContinuityProjector keeps the factorisation (it depends on the grid and the degree only), so
// that a fit projecting several times factorises once.
#pragma once

#include <memory>
#include <vector>

#include "model/bernstein/bernstein_mesh.h"

namespace implicitfit {

class ContinuityProjector {
 public:
  ContinuityProjector(const BernsteinGrid& grid, int k, int continuity);
  ~ContinuityProjector();
  // As ProjectOntoContinuitySpace below, with the stored factorisation.
  double Project(std::vector<double>* b) const;

 private:
  struct Factor;
  BernsteinGrid grid_;
  int k_, continuity_;
  std::unique_ptr<Factor> factor_;  // null when there are no rows (one tetrahedron)
};

// Replaces b by its orthogonal projection onto ker C; returns the largest |C b| after it,
// relative to max |b| (model/bernstein/bernstein_mesh_continuity.h ContinuityDefect).
double ProjectOntoContinuitySpace(const BernsteinGrid& grid, int k, int continuity,
                                  std::vector<double>* b);

}  // namespace implicitfit
