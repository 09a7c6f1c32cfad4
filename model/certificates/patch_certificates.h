// Certificates of a Bernstein patch beyond the plain A^mu test (model/certificates/convexity_certificate.h):
// docs/maths.md G-2 (label-invariant margin, Hessian bound) and G-4 (tangent-restricted
// certificate, patch-localised verdict).
//
// G-2. The Cartesian matrices C^mu = E^-T A^mu E^-1 (E = [x1 - x4, x2 - x4, x3 - x4]) do not
// depend on the vertex labelling (Hess f = k(k-1) sum_mu B_mu(tau) C^mu is label-free, and so is
// its Bernstein expansion), unlike A^mu itself.
//   min_eigenvalue_cartesian = min_mu lambda_min(C^mu)       (units of f per length^2)
//   hessian_lower_bound      = k(k-1) min_eigenvalue_cartesian
// is a proven lower bound of lambda_min(Hess f(x)) for x in T: Hess f(x) is k(k-1) times a
// convex combination of the C^mu there and lambda_min is concave. Degree 1: both 0.
//
// G-4 (a), tangent-restricted (Finsler) certificate, still global on T. With phi(s) = s + c s^2/2,
// c > 0 and 1 + c min_lambda b_lambda > 0, phi is increasing on the range of f over T (f >= min b
// by the convex hull property) and phi(0) = 0, so {f <= 0} n T = {f~ <= 0} n T for f~ = phi o f,
// a degree-2k polynomial: f elevated k times plus (c/2) f^2, where
//   (f^2)_nu = sum_{lambda + lambda' = nu} b_lambda b_lambda' [k!/lambda!][k!/lambda'!] /
//   [(2k)!/nu!].
// If every A^mu of f~ (optionally degree-elevated) is positive definite, the solid is convex on T.
// c is searched on (0, 0.999/max(0, -min b)) by a log grid then golden section on the margin
// (the margin normalised by max|b~| so different c compare); c = 0 (f elevated to 2k) is tried
// first, so everything the plain certificate certifies stays certified.
//
// G-4 (b), patch-localised verdict (Guo's Theorem 1 as stated: second-order convexity at every
// patch point, NOT the global half-space property): T is bisected at its longest edge
// recursively (control points of a sub-tetrahedron by blossoming: b'_lambda is the blossom of f
// at y1^l1 y2^l2 y3^l3 y4^l4); sub-tetrahedra whose control points are strictly one sign hold no
// patch point and are dropped; the rest must pass the A^mu test by depth `max_depth`.
// `locally_convex` is a separate verdict from `convex`: two separate convex sheets in one T are
// locally convex but not convex.
#pragma once

#include <vector>

#include "model/bernstein/bernstein_patch.h"

namespace implicitfit {

struct CartesianMargin {
  double min_eigenvalue_cartesian = 0.0;
  double hessian_lower_bound = 0.0;
};
CartesianMargin CartesianConvexityMargin(int k, const Tetrahedron& tet, const double* b);

// f^2 of a degree-k patch as a degree-2k patch.
std::vector<double> BernsteinSquare(int k, const double* b);

struct FinslerOptions {
  int extra_elevation = 2;  // degree elevations of f~ beyond 2k (each can only help)
  int grid = 12;            // log-spaced c values before the golden-section refinement
  int golden_steps = 20;
};
struct FinslerCertificate {
  bool convex = false;  // the solid {f <= 0} n T is certified convex
  double c = 0.0;       // the c used (best margin found)
  double margin = 0.0;  // min eigenvalue of the A^mu of f~ / max|b~| at that c
  int degree = 0;       // degree of f~ that was certified (2k + extra_elevation)
};
// k >= 2 (degree 1 is affine: convex, c = 0).
FinslerCertificate CertifyFinsler(int k, const double* b, const FinslerOptions& options = {});

// Control points of the same polynomial on the sub-tetrahedron whose vertices have barycentric
// coordinates (with respect to the patch's tetrahedron) given by the rows of `tau`.
std::vector<double> SubTetrahedronControlPoints(int k, const double* b, const double tau[4][4]);

struct LocalConvexity {
  bool locally_convex = false;
  int pieces_certified = 0;  // sub-tetrahedra certified by A^mu
  int pieces_dropped = 0;    // sub-tetrahedra without patch points (control points one sign)
  int max_depth_reached = 0;
};
LocalConvexity CertifyLocalConvexity(int k, const double* b, int max_depth = 16);

}  // namespace implicitfit
