// Minimum-zone (Chebyshev) association, the ISO 1101 evaluation of form tolerances: the
// primitive theta minimising t = max_i |d_i(theta)|, d_i the exact signed orthogonal distance;
// the zone is {x : |d(x)| <= t} (two parallel planes, concentric spheres, coaxial cylinders,
// coaxial cones of the same angle), its width 2t is the form error.
//
// Method: sequential linear programming, each linear Chebyshev problem solved exactly by the
// exchange algorithm (Stiefel; the dual simplex of the LP min t s.t. |d_i + g_i delta| <= t).
// With k free parameters (fit/primitive_tangent.h) a reference is a set S of k + 1 points:
//   1. signs: the null vector c of the k x (k+1) matrix [g_i] (i in S) gives sigma_i = sgn c_i
//      (the alternation of the reference; lambda_i = |c_i| / sum |c| are the LP multipliers);
//   2. Newton on the nonlinear levelled equations d_i(theta) = sigma_i h, i in S (k + 1
//      equations, unknowns theta and h): quadratic convergence to machine precision;
//   3. if some |d_j| > h the worst point enters the reference and the point chosen by the ratio
//      test (min lambda_i / mu_i over mu_i > 0, A_S mu = [sigma_j g_j; 1]) leaves; else stop.
// Why not p-norm continuation: sum |d_i|^p only approaches max |d_i| as N^(1/p), needs p in the
// hundreds to reach 1e-12 and is then ill-conditioned; the exchange ends on the exact active set
// and yields its optimality certificate for free. Why not a generic LP solver: the LPs have
// k + 1 <= 7 unknowns, where one exchange step is a (k+1) x (k+1) solve.
// Start: the least-squares fit (fit/least_squares_fit.h); S is seeded by decreasing |d_i|, each
// point kept when it raises the rank of [g_i; 1] (an invertible reference).
// Optimality conditions checked at the end (first-order, Kuhn-Tucker for min t s.t.
// sigma_i d_i <= t): every multiplier lambda_i > 0 with sum lambda_i sigma_i g_i = 0 and
// sum lambda_i = 1, every point inside the zone; since the size parameter (offset, radius,
// angle-offset) has g = -1 at every point, sum lambda_i sigma_i = 0: contacts on both sides.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "fit/least_squares_fit.h"
#include "model/model.h"

namespace implicitfit {

struct MinimumZoneResult {
  bool success = false;
  std::string message;
  std::vector<double> parameters;   // the zone's middle surface, input frame
  double zone_width = 0.0;          // 2 t: the minimum-zone form error
  FormFigures figures;              // of the result (form_error = zone_width up to rounding)
  std::vector<int> contacts;        // the reference: indices of the points on the zone's faces
  std::vector<int> sides;           // +1: on the outer face (d = +t), -1: on the inner face
  std::vector<double> multipliers;  // lambda_i of the contacts
  int outer_contacts = 0, inner_contacts = 0;
  bool optimality_verified =
      false;          // every lambda_i >= -1e-9, every |d_i| <= t (1 + 1e-9), both faces touched
  int exchanges = 0;  // reference changes
};

// Plane, sphere, cylinder and cone (a torus has no guarantee of the Haar condition here).
MinimumZoneResult MinimumZoneFit(NodeType kind, const std::vector<Eigen::Vector3d>& points,
                                 const std::vector<double>& least_squares_start);

}  // namespace implicitfit
