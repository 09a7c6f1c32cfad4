// Exact projection of a Bernstein mesh's control points onto its continuity space ker C
// (model/bernstein_mesh_continuity.h: C0 rows, plus C1 rows for continuity 1).
//
// Maths. The orthogonal projection of b onto ker C is the least-squares residual of
// C^T y ~ b: b - C^T y* is orthogonal to range(C^T) = (ker C)^perp, whatever least-squares
// solution y* is taken (C has redundant rows, so y* is not unique but the residual is).
// y* comes from SuiteSparseQR (rank-revealing sparse QR, through Eigen's SPQR module), so the
// redundant rows are detected instead of making the system singular. One refinement pass
// (the same projection applied to the result) removes the rounding of the first.
#pragma once

#include <vector>

#include "model/bernstein_mesh.h"

namespace implicitfit {

// Replaces b by its orthogonal projection onto ker C; returns the largest |C b| after it,
// relative to max |b| (model/bernstein_mesh_continuity.h ContinuityDefect).
double ProjectOntoContinuitySpace(const BernsteinGrid& grid, int k, int continuity,
                                  std::vector<double>* b);

}  // namespace implicitfit
