// The linearised Chebyshev problem of the minimum-zone fit (fit/metrology/minimum_zone.h), solved exactly:
//   minimise t over (y, t)  subject to  -t <= d_i + g_i . y <= t   (i = 1..n),
//                                       |y_j| <= radius            (j = 1..k; none if radius <= 0)
// a linear programme with k + 1 unknowns and 2 n rows. GLPK's primal simplex finds an optimal
// basis in double precision; glp_exact then re-solves from that basis in exact rational
// arithmetic (the doubles d_i, g_ij, radius taken as exact rationals), so the optimum, the step
// y and the multipliers are exact up to their final rounding to double.
// Multipliers (the LP's dual values): lambda_i >= 0 on the rows that hold with equality,
// side_i = +1 for d_i + g_i y = +t, -1 for -t; optimality of the LP without a trust region is
//   sum_i lambda_i = 1,  sum_i lambda_i side_i g_i = 0,
// the Kuhn-Tucker conditions of the minimax problem at y = 0 when the optimum t equals max |d_i|.
// Why GLPK: a maintained Debian LP library (libglpk-dev) with an exact-arithmetic simplex, which
// a hand-written exchange (the previous solver here, which could cycle on near-degenerate
// contact sets) does not give.
#pragma once

#include <Eigen/Core>
#include <string>

namespace implicitfit {

struct ChebyshevLpSolution {
  bool success = false;
  std::string message;         // GLPK's status when success is false
  Eigen::VectorXd step;        // y (k)
  double t = 0.0;              // the optimal max_i |d_i + g_i y|
  Eigen::VectorXd lambda;      // n multipliers (0 on rows that do not hold with equality)
  Eigen::VectorXi side;        // n: +1 / -1 for the face each multiplier belongs to, 0 if none
  bool radius_active = false;  // some |y_j| = radius with a nonzero multiplier
};

ChebyshevLpSolution SolveChebyshevLp(const Eigen::VectorXd& d, const Eigen::MatrixXd& g,
                                     double radius);

}  // namespace implicitfit
