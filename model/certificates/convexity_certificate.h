// Convexity certificate of a Bernstein patch of degree k >= 2 (Guo §4, generalised; docs/design.md).
//
// Maths. For every mu with |mu| = k - 2 the symmetric 3x3 matrix
//   A^mu_ij = b(mu + e_i + e_j) + b(mu + 2 e_4) - b(mu + e_i + e_4) - b(mu + e_j + e_4),  i, j
//   = 1..3
// (Guo eq. 7 without the factor k(k-1)). With sigma_4 = -(sigma_1 + sigma_2 + sigma_3) the
// barycentric second derivative is sum_ij d2f/dtau_i dtau_j sigma_i sigma_j
//   = k(k-1) sigma^T A(tau) sigma,  A(tau) = sum_mu B^{k-2}_mu(tau) A^mu,
// a convex combination inside the tetrahedron, and the Cartesian Hessian is
//   Hess f = k(k-1) E^-T A(tau) E^-1,  E = [x1 - x4, x2 - x4, x3 - x4].
// So all A^mu positive definite => f is convex on the tetrahedron => the solid {f <= 0} is
// convex there and the patch is convex in Guo's sense (the surface lies on the side of every
// tangent plane that -grad f points to). The certificate does not depend on the vertices.
//
// Decision (stated tolerance): A^mu counts as positive definite iff its smallest eigenvalue
// (closed form, model/certificates/symmetric_eigen3.h, error a few machine epsilons times |A^mu|) exceeds
// kConvexityTolerance * |A^mu|_F. min_eigenvalue is the smallest eigenvalue over all A^mu, in
// control-point units (no k(k-1) factor).
// Degree 1 (a plane, Hessian zero): convex (it bounds a half-space), min_eigenvalue 0, no
// matrices. No heap allocation (except for control points beyond 1e150 or below 1e-150 in
// magnitude, certified after an exact power-of-two scaling so A^mu cannot overflow): fit for
// millions of patches per second.
#pragma once

namespace implicitfit {

constexpr double kConvexityTolerance = 1e-12;

struct ConvexityCertificate {
  bool convex = false;
  double min_eigenvalue = 0.0;  // smallest eigenvalue over all A^mu (0 for degree 1)
  int num_matrices = 0;         // (k-1)k(k+1)/6 for k >= 2
};

// A^mu of a degree-k patch, mu = (k-2-m2-m3-m4, m2, m3, m4), as {a11, a22, a33, a12, a13, a23}.
void GuoMatrix(int k, const double* control_points, int m2, int m3, int m4, double a[6]);

ConvexityCertificate CertifyConvexity(int k, const double* control_points);

}  // namespace implicitfit
