// Convex Bernstein patch fits at their optimum (fit --model quadric-patch|cubic-patch --convex,
// with or without Guo's shape constraints; docs/convexity.md "What --convex optimises").
//
// Objective. Over the certified-convex patches (every A^mu positive definite with the margin
// lambda_min(A^mu) >= kConvexRelativeMargin max |b| of the patch as written), minimise
//   sum_i rho(r_0,i^2 + w^2 |grad f / |grad f| - n_i|^2),  r_0 = f(p_i) / |grad f(p_i)|,
// rho the Cauchy loss of scale c = 3 x the smallest RMS of r_0 over the starts below (so the
// scale follows the misfit a convex patch must have on non-convex data instead of the
// unconstrained fit's noise level, which would make every point an outlier), floored by the
// unconstrained fit's scale. f / |grad f| and the unit normals do not change when b is scaled,
// so the scale of b is fixed during the fit (scale normalisation): b, or the degree-2
// parameters z below, move on a unit sphere.
//
// Degree 2, exact parameterisation (every iterate certified): A = L L^T + m I (L lower
// triangular, 6 numbers), plus b_1001, b_0101, b_0011, b_0002; z = (L, those 4) on the unit
// sphere S^9. With |z| = 1, max |b| <= |L|^2 + m + |b_0002| + 2 max |b_i4| <= sqrt(5) + m, so
// m = 1e-5 guarantees lambda_min(A) / max |b| >= 4.4e-6 > 1e-6 for the written patch.
// Starts (each refined for a few iterations, the one with the lowest cost refined to the end):
//   plane    the total-least-squares plane of the points, oriented by the normals, with a
//            curvature of 1e-3 / R (a plane is convex, and a convex patch can always do as
//            well as one: the solid below a saddle is not convex, the plane is the fallback);
//   project  the unconstrained degree-2 fit with the negative eigenvalues of its Cartesian
//            Hessian clamped (its nearest convex quadric in the Hessian);
//   clamp    the same clamping of Guo's A in barycentric coordinates.
// Degree 3, 4: the best degree-2 convex fit (margin 1e-4, so that it keeps >= 1e-6 after
// elevation: the elevated A^mu are (k-1)/(k+1) times convex combinations of the old) elevated
// to degree k, then refined by step rejection: a guard block fails any iterate whose certificate
// misses the margin, Ceres rejects the step and shrinks its trust region.
// Shape constraints (b = N y, fit/bernstein/patch_shape_constraints.h) with --convex: the
// convex fit without them is moved onto the subspace by the affine function that makes it
// meet the constraints (adding an affine function leaves every A^mu unchanged: they are second
// differences); when no affine function can (more than 2 vertex normals + through-vertices
// than an affine function has freedom), the most convex point of the subspace is found by
// Kelley's cutting planes (fit/bernstein/convex_feasible_start.h) and the start is the nearest
// convex combination of it and the projection that is certified. Then step rejection on the
// subspace (unit sphere within it). A patch through an edge cannot be strictly convex (f = 0
// along the edge makes its second derivative there 0): refused by PatchFitOptions::IsValid.
// The result is certified and its margin verified; otherwise the fit fails (never a
// non-convex result under --convex).
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "fit/bernstein/patch_residuals.h"
#include "model/bernstein/bernstein_patch.h"

namespace implicitfit {

constexpr double kConvexRelativeMargin = 1e-6;

struct ConvexPatchProblem {
  int degree = 2;
  Tetrahedron tetrahedron;
  const std::vector<Eigen::Vector3d>* points = nullptr;
  const std::vector<Eigen::Vector3d>* normals = nullptr;  // may be empty
  double normal_weight = 0.1;
  int max_iterations = 200;
  double free_loss_scale = 0.0;  // the unconstrained fit's Cauchy scale (the floor)
  Eigen::MatrixXd subspace;      // shape constraints: b = N y (orthonormal N); empty: none
};

struct ConvexPatchFit {
  bool success = false;
  std::string message;
  std::vector<double> control_points;
  SolveOutcome outcome;           // of the last solve
  std::string start;              // plane | project | clamp (degree 2 start that won)
  double loss_scale = 0.0;        // c of the objective
  double relative_margin = 0.0;   // min_mu lambda_min(A^mu) / max |b| of the result
  int starts = 0;                 // starts tried
};

// free2: the unconstrained degree-2 fit (control points), the starts' source.
ConvexPatchFit FitConvexPatch(const ConvexPatchProblem& problem, const std::vector<double>& free2);

// min_mu lambda_min(A^mu) / max |b| (-inf when some A^mu is not certified positive definite).
double CertifiedRelativeMargin(int k, const std::vector<double>& b);

}  // namespace implicitfit
