// Convexity certificate of a bspline_volume on its box (docs/maths.md TB-3, derived in the spirit
// of Guo's Bernstein criterion).
//   1. Per axis, knot insertion (Boehm) raises every interior knot to multiplicity k: the
//      coefficients become the Bezier coefficients of every cell, so on a cell of size
//      h_x x h_y x h_z with local t in [0, 1]^3, f = sum_a b_a B^k_a1(t_x) B^k_a2(t_y) B^k_a3(t_z).
//   2. The Hessian's entries are tensor Bernstein polynomials of the differences of b:
//        f_xx = k (k - 1) / h_x^2 sum (b_{a+2e1} - 2 b_{a+e1} + b_a) B^(k-2, k, k),
//        f_xy = k^2 / (h_x h_y) sum (b_{a+e1+e2} - b_{a+e1} - b_{a+e2} + b_a) B^(k-1, k-1, k),
//      (the others alike); every entry is degree-elevated per axis to (k, k, k)
//      (c'_i = i/(m+1) c_{i-1} + (1 - i/(m+1)) c_i), so H(t) = sum_a B^k_a(t) H_a with symmetric
//      3 x 3 matrices H_a.
//   3. The Bernstein basis is non-negative and sums to 1, so H(t) is a convex combination of the
//      H_a: every H_a positive definite => H(t) positive definite on the cell => f convex on the
//      cell. f is C^(k-1), at least C^1 for k >= 2, and a C^1 function convex on every cell of a
//      convex box is convex on the box (along any segment its derivative is continuous and
//      non-decreasing on each piece). Degree 1 (C^0 only, zero diagonal) is never certified.
// The eigenvalues are in Cartesian units (the same under any relabelling of the axes).
#pragma once

#include <vector>

#include "model/splines/spline_structure.h"

namespace implicitfit {

struct VolumeConvexityCertificate {
  bool convex = false;              // every cell certified (degree >= 2)
  int cells = 0, certified_cells = 0;
  double min_eigenvalue = 0.0;      // smallest eigenvalue over every H_a of every cell
  int worst_cell = -1;              // the cell holding it (x fastest)
  std::vector<double> cell_min_eigenvalues;  // per cell, x fastest
};

// Certifies the volume with coefficients c; a cell is certified when its smallest eigenvalue
// exceeds `margin` (>= 0).
VolumeConvexityCertificate CertifyVolumeConvexity(const SplineStructure& s, const double* c,
                                                  double margin = 0.0);

// Per axis: the matrix that maps the n_a + k B-spline coefficients to the k n_a + 1 Bezier
// coefficients of the cells (row c k + j: coefficient j of cell c), by knot insertion.
std::vector<std::vector<double>> BezierExtraction(const std::vector<double>& knots, int degree,
                                                  int count);

}  // namespace implicitfit
