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
//
// Refined grids (model/bernstein/grid_refinement.h). A face of a finer tetrahedron T that lies
// on a face of a coarser one T' (a hanging face) is inside one of T''s face triangles (the Kuhn
// splits are nested), and C^r across it holds iff the control points of T with power j <= r on
// its vertex opposite the face equal those of T''s polynomial re-expressed on T
// (model/bernstein/bernstein_conversion.h ReexpressionMatrix M): b^T_lambda - (M b^T')_lambda = 0.
// The same rows, with T first, join the conforming faces' rows. C0 parametrization: the
// control points of every leaf level are identified by position within the level (as on a
// uniform grid), except those on a hanging face, edge or vertex sigma of T (sigma = T meet T'
// for a coarser tetrahedron T' touching T: a face of T, spanned by T's vertices inside T'),
// which are T''s re-expressed ones (levels processed coarse to fine, so T''s own are known):
// b = P w with P sparse, exact C0 for every w. Sharp faces (grid.sharp) keep their C0 rows and
// lose those of order >= 1 (creases: C0 only), unless asked for (the certificate's kink test).
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
  // For each row: the face (the opposite vertex's index) of the first tetrahedron, and whether
  // it is declared sharp (C0 only).
  std::vector<int> face;
  std::vector<bool> sharp;
};

// The rows for j = min_order..max_order over every interior face of the grid (on refined grids
// also the hanging faces); rows of order >= 1 on sharp faces only with include_sharp. Row r is
// b^{first}_lambda - (the second tetrahedron's polynomial re-expressed on the first)_lambda, so
// its sign is that of the jump of f entering the first tetrahedron (certificate's kink test).
ContinuityRows BernsteinContinuityRows(const BernsteinGrid& grid, int k, int min_order,
                                       int max_order, bool include_sharp = false);

// Index of each control point (tetrahedron-major) in the global domain-point lattice
// (k nx + 1)(k ny + 1)(k nz + 1): the C0 identification, b = P w. Uniform grids only
// (std::invalid_argument on a refined grid: use BernsteinC0Parametrization).
std::vector<long long> DomainPointIndices(const BernsteinGrid& grid, int k);
long long NumDomainPoints(const BernsteinGrid& grid, int k);

// The C0 spline space of any grid as b = P w (see the header): P sparse, rows = control points,
// columns = unknowns; identity[i] = the unknown control point i equals (P's row i is that unit
// row), -1 for the control points of hanging faces. On a uniform grid P is the domain-point map
// (identity = DomainPointIndices).
struct C0Parametrization {
  Eigen::SparseMatrix<double, Eigen::RowMajor> P;
  std::vector<long long> identity;
  long long unknowns = 0;
};
C0Parametrization BernsteinC0Parametrization(const BernsteinGrid& grid, int k);

// A basis N (columns) of the C^continuity spline space (continuity 0 or 1): every b = N z
// satisfies the rows; dense, (tetrahedra * N(k)) x dimension. For continuity 0 it is P itself
// (0/1 columns on a uniform grid), for 1 it is P K with K orthonormal.
Eigen::MatrixXd BernsteinSplineBasis(const BernsteinGrid& grid, int k, int continuity);

// Largest |C b| over the C0 and (continuity 1) C1 rows (not those of sharp faces), relative to
// max |b| (0 for b = 0).
double ContinuityDefect(const BernsteinGrid& grid, int k, int continuity, const double* b);

}  // namespace implicitfit
