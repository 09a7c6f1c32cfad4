// Minimum-zone (Chebyshev) association, the ISO 1101 evaluation of form tolerances: the
// primitive theta minimising t = max_i |d_i(theta)|, d_i the exact signed orthogonal distance;
// the zone is {x : |d(x)| <= t} (two parallel planes, concentric spheres, coaxial cylinders,
// coaxial cones of the same angle), its width 2t is the form error.
//
// Method: sequential linear programming with a trust region (Madsen's minimax method), from the
// least-squares fit (fit/metrology/least_squares_fit.h). With k free parameters (fit/metrology/primitive_tangent.h)
// and the distances linearised at theta, d_i(theta + delta) ~ d_i + g_i delta, each step solves
//   min t  s.t.  |d_i + g_i delta| <= t,  |delta_j| <= radius   (scaled columns)
// exactly (fit/metrology/chebyshev_lp.h: GLPK simplex, then its exact rational simplex). The step is taken
// when max_i |d_i| really falls by at least 1% of the decrease the LP predicts, and the radius
// adapts to that ratio (doubled above 75%, quartered below 1%). max |d_i| decreases strictly
// at every accepted step, so the iteration cannot cycle (the exchange it replaces did, on
// near-degenerate contact sets); it stops when the LP predicts a decrease below 1e-13 of t.
// Polish: when k + 1 points lie within 1e-6 t of the faces, Newton on the levelled equations
// d_i(theta) = sigma_i h (those points) reaches machine precision; kept only if it does not
// widen the zone.
// Optimality certificate (first-order Kuhn-Tucker conditions of min t s.t. |d_i| <= t): over the
// points within 1e-8 t of the zone's faces (sigma_i their face), multipliers lambda_i >= 0 with
// sum lambda_i = 1 and sum lambda_i sigma_i g_i = 0; the residual
// r = min_lambda |sum lambda_i sigma_i g_i|_1 (columns scaled so that a unit move changes some
// distance by t) is computed exactly as the LP's optimum over a small box, and must be <= 1e-6.
// Since the size parameter (offset, radius, angle-offset) has the same gradient at every point,
// sum lambda_i sigma_i = 0: contacts on both faces. The contacts are usually k + 1 (the Haar
// case, where the SLP converges quadratically); fewer when the optimum is held by curvature
// (seen on cylinders and cones probed on few circles), where it converges linearly. There the
// first-order conditions do not imply a minimum: the curvature of the Lagrangian
// sum lambda_i sigma_i d_i along the directions that keep the contacts levelled (null space of
// [sigma_i g_i, -1]) is computed by a central second difference and must not be negative; and,
// since the problem is not convex and such flat optima can sit next to a narrower one, the SLP
// restarts from moves both ways along that direction (0.3, 0.03, 0.003 of a unit) and along
// every parameter (1 and 0.1 of a unit; a unit move changes some distance by t), keeping the
// narrowest zone, until no restart narrows it (at most 5 rounds).
// Exchange search: the problem is not convex, and on near-degenerate sets (a torus probed on its
// outer side trades R against r along an almost flat valley) the SLP from the least-squares fit
// can stop in a certified local minimum a hair wider than another one whose contact set differs
// by one point. With k + 1 contacts, every exchange of one contact for one other point (on
// either face) is tried: Newton on the new set's levelled equations from the current zone; a
// solution holding every point and narrower than the current zone is descended from again (at
// most 10 rounds). `contact_swaps` counts the exchanges that narrowed the zone.
// Why not p-norm continuation: sum |d_i|^p only approaches max |d_i| as N^(1/p), needs p in the
// hundreds to reach 1e-12 and is then ill-conditioned; the LP gives the exact active set and its
// certificate.
#pragma once

#include <Eigen/Core>
#include <cmath>
#include <string>
#include <vector>

#include "fit/metrology/least_squares_fit.h"
#include "model/model.h"

namespace implicitfit {

// Largest Kuhn-Tucker residual accepted as stationary (scaled gradients: a unit move changes
// some distance by the half width t, so no direction narrows the zone faster than 1e-6 t per
// such move).
constexpr double kMinimumZoneKktTolerance = 1e-6;

struct MinimumZoneResult {
  bool success = false;
  std::string message;
  std::vector<double> parameters;   // the zone's middle surface, input frame
  double zone_width = 0.0;          // 2 t: the minimum-zone form error
  FormFigures figures;              // of the result (form_error = zone_width up to rounding)
  std::vector<int> contacts;        // the reference: indices of the points on the zone's faces
  std::vector<Eigen::Vector3d> contact_points;  // those points (input frame)
  std::vector<double> contact_distances;        // their signed distances (+-t up to rounding)
  std::vector<int> sides;           // +1: on the outer face (d = +t), -1: on the inner face
  std::vector<double> multipliers;  // lambda_i of the contacts
  int outer_contacts = 0, inner_contacts = 0;
  // Kuhn-Tucker residual <= 1e-6, both faces touched, no negative second-order curvature
  bool optimality_verified = false;
  double kkt_residual = 0.0;  // min |sum lambda_i sigma_i g_i|_1 over the multipliers (scaled)
  int exchanges = 0;          // changes of the contact set between accepted steps
  int iterations = 0;         // LP steps (accepted or not)
  // With fewer than k + 1 contacts: the least curvature of the Lagrangian along the directions
  // keeping the contacts levelled (relative to t; must not be negative); +inf otherwise.
  double second_order_curvature = INFINITY;
  int escapes = 0;  // restarts from saddle points (negative curvature) that narrowed the zone
  int contact_swaps = 0;  // exchanges of one contact that narrowed the zone (see above)
};

// Plane, sphere, cylinder, cone and torus (the torus' zone: two tori of the same centre, axis and
// major radius, minor radii r +- t). The method needs no Haar condition: with fewer than k + 1
// contacts the second-order check and the restarts above decide. Above `direct_limit` points the
// LPs run on working sets (the exchange of minimum_zone.cc: the same optimum, certified on the
// whole cloud; 20 000 noisy sphere points took over 100 s in one LP, 0.9 s by the exchange).
MinimumZoneResult MinimumZoneFit(NodeType kind, const std::vector<Eigen::Vector3d>& points,
                                 const std::vector<double>& least_squares_start,
                                 int direct_limit = 1500);

}  // namespace implicitfit
