// Continuity between the patches of a Bernstein mesh (docs/maths.md G-1), as linear rows C b = 0 on
// the mesh's control points b (all tetrahedra, model/bernstein/bernstein_mesh.h layout), and a basis of
// the continuous spline space.
//
// Maths. T = [x1 x2 x3 x4] and T' = [x1 x2 x3 x5] share the face [x1 x2 x3] (matched by
// vertex); alpha = barycentric coordinates of x5 with respect to T (on a Kuhn grid they are
// integers). For a multi-index of T' with power j on x5 and lambda the face part (|lambda| =
// k - j, mapped to T's vertices),
//   b'_{lambda + j e5} = sum_{|nu| = j} b_{lambda + nu} B^j_nu(alpha)     (j de Casteljau steps)
// holds for j = 0..r iff the patches join C^r across the face. C0 is the j = 0 rows (shared
// control points coincide), C1 adds j = 1, and the j = 2 rows alone are the soft C2
// regularisation of the fitter. Per interior face C(k+2, 2) rows for j = 0 and C(k+1, 2) for
// j = 1. The rows have redundancies (the spaces' dimensions come from ranks, not row counts).
//
// Spline space basis. C0 meshes are exactly the meshes whose control points are values at the
// global domain points (lattice of spacing h/k, (k nx + 1)(k ny + 1)(k nz + 1) of them): b = P w
// with P a 0/1 selection. C1 adds the j = 1 rows, G = C1 P, and the basis is
// N = P K with K an orthonormal basis of ker G (column-pivoted Householder QR of G^T with a
// relative threshold; the singular values of these rows have a clear gap, docs/maths.md G-1).
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <vector>

#include "model/bernstein/bernstein_mesh.h"

namespace implicitfit {

struct ContinuityRows {
  Eigen::SparseMatrix<double, Eigen::RowMajor> C;  // rows x (tetrahedra * N(k))
  // For each row: the two tetrahedra it couples (T' first, T second).
  std::vector<std::pair<long long, long long>> tetrahedra;
  // For each row: the power j of the vertex opposite the shared face.
  std::vector<int> order;
};

// The rows for j = min_order..max_order over every interior face of the grid.
ContinuityRows BernsteinContinuityRows(const BernsteinGrid& grid, int k, int min_order,
                                       int max_order);

// Index of each control point (tetrahedron-major) in the global domain-point lattice
// (k nx + 1)(k ny + 1)(k nz + 1): the C0 identification, b = P w.
std::vector<long long> DomainPointIndices(const BernsteinGrid& grid, int k);
long long NumDomainPoints(const BernsteinGrid& grid, int k);

// A basis N (columns) of the C^continuity spline space (continuity 0 or 1): every b = N z
// satisfies the rows; dense, (tetrahedra * N(k)) x dimension. For continuity 0 it is P itself
// (0/1 columns), for 1 it is P K with K orthonormal.
Eigen::MatrixXd BernsteinSplineBasis(const BernsteinGrid& grid, int k, int continuity);

// Largest |C b| over the C0 and (continuity 1) C1 rows, relative to max |b| (0 for b = 0).
double ContinuityDefect(const BernsteinGrid& grid, int k, int continuity, const double* b);

}  // namespace implicitfit
