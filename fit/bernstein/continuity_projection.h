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
// Refined grids (model/bernstein/grid_refinement.h) take another route to the same projection,
// because SuiteSparseQR's rank detection is not reliable there: on the chamfered block's grid
// after one round of refinement (8 x 7 x 6 cubes, 64 split, 5 418 tetrahedra) the "projected"
// random control points kept a C1 defect of 1.06 (relative to max |b|), and at three levels the
// factorisation ran for minutes. The C1 rows of a refined grid have singular values spread down
// to ~3e-4 of the typical one (measured: the rate of the iteration below at small mu), with no
// gap for a rank threshold to find. There the projection onto ker Gh (Gh = G D^-1/2) is the
// method of multipliers: v_{j+1} = (I + mu Gh^T Gh)^-1 v_j, which keeps ker Gh and damps every
// other singular direction by 1 / (1 + mu s^2) per step (its fixed point is the orthogonal
// projection: v_0 - v_j stays in range Gh^T), with one CHOLMOD factor of the nonsingular
// I + mu Gh^T Gh, mu = 1e8 / mean diag(Gh^T Gh), until max |Gh v| <= 1e-15 max |v_0| (at most
// kMaxMultiplierSteps); each step solves for the change, (I + mu Gh^T Gh)^-1 mu Gh^T Gh v, so
// that the rounding of the solve (condition ~ mu) scales with the shrinking defect, not with v.
// Measured on that grid: about 12 steps, defect 5e-16, 0.8 s instead of 10 s; applied again, or
// to a C1 mesh of the base grid re-expressed on the refined one, it moves nothing by more than
// 5e-14 of max |b| (tests/fit/bernstein/adaptive_mesh_fitter_test.cc). Uniform grids keep the
// QR (exact there, every benchmark figure made with it).
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
