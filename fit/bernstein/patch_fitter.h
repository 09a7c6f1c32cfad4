// Fitting a Bernstein-Bezier patch (model/bernstein/bernstein_patch.h) of degree 2..4 to an oriented
// cloud (fit --model quadric-patch|cubic-patch [--degree k] [--convex]).
//
// Tetrahedron: the user's, or by default the regular tetrahedron whose inscribed sphere has
// radius 1.1 R around the centroid c, R = max |p_i - c| (so the cloud lies inside with a 10%
// margin): vertices c + 3.3 R v_i, v_i = (+-1, +-1, +-1)/sqrt(3) with an even number of minus
// signs.
// 1. Linear initialisation (Eigen, least squares): f(p_i) = 0, f(p_i +- h n_i) = +-h, h = 1% of
//    R, linear in the control points; it fixes the scale, so f = 0 is excluded.
// 2. Ceres refinement of r_0 = f / |grad f| (first-order geometric distance) and the normal term
//    w (grad f / |grad f| - n) (signed: grad f follows the normals' orientation), grad f analytic
//    (de Casteljau), Cauchy loss at 3 sigma of the initial fit.
// 3. --convex (fit/bernstein/convex_patch_fit.h): every A^mu of docs/design.md positive definite
//    with the margin lambda_min(A^mu) >= 1e-6 max|b| of the WRITTEN patch (scale-invariant),
//    at the optimum of a stated objective: several certified starts (the least-squares plane,
//    the unconstrained fit projected onto the convex set, its barycentric clamp), the loss
//    scale from the best start's misfit, the scale of b normalised (unit sphere), the lowest
//    cost kept; degree 2 by an exact parameterisation (every iterate certified), degree >= 3
//    and shape constraints by step rejection from a certified start. The result is verified
//    with CertifyConvexity and the margin; if either fails, the fit fails (never a non-convex
//    result under --convex).
#pragma once

#include <Eigen/Core>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "fit/common/fit_summary.h"
#include "fit/bernstein/patch_shape_constraints.h"
#include "model/bernstein/bernstein_patch.h"
#include "model/model.h"

namespace implicitfit {

struct PatchFitOptions {
  int degree = 2;                // 2..4
  bool convex = false;           // enforce and certify convexity
  bool has_tetrahedron = false;  // use `tetrahedron` instead of the default enclosing one
  Tetrahedron tetrahedron;
  double normal_weight = 0.1;  // w of the normal residuals
  int max_iterations = 200;
  // Guo §3 shape control (fit/bernstein/patch_shape_constraints.h): exact linear equalities,
  // also with `convex` (a subspace of the convex fit), except through an edge.
  PatchShapeConstraints constraints;
  // False (with a reason) for a degree outside 2..4, a through-edge constraint with `convex`,
  // conflicting constraints, a negative or non-finite weight or fewer than 1 iteration.
  bool IsValid(std::string* error) const;
};

// message: "converged", "no convergence within ...", or why it failed. termination: how the
// last solve ended: NO_CONVERGENCE (the iteration limit came first) is a usable, successful
// result that is not converged; FAILURE makes success false.
struct PatchFitResult : FitSummary {
  int degree = 0;
  bool convex_constraint = false;  // options.convex
  Tetrahedron tetrahedron;
  std::vector<double> control_points;
  double rms = 0.0;                   // RMS of f/|grad f| over all points
  double mean_normal_angle_deg = -1;  // mean angle between grad f and the normals (signed:
                                      // 0..180 deg, > 90 when grad f points against them)
  double mean_normal_cosine = 0.0;    // mean of grad f . n / |grad f| (signed; 0 without normals)
  double unconstrained_rms = -1.0;    // --convex: RMS of the same fit without the constraint
  double min_eigenvalue = 0.0;        // certificate margin (smallest A^mu eigenvalue)
  bool certified_convex = false;
  double relative_margin = 0.0;       // --convex: min_eigenvalue / max |b| (>= 1e-6 required)
  std::string convex_start;           // --convex: the degree-2 start that won (plane, project,
                                      // clamp)
  Model ToModel() const;
  // "points N  rms ...  certified convex ...  s" (one line).
  std::string BriefReport() const;
  // The report of fit/common/fit_report.h; `normals` says where the normals came from.
  nlohmann::json ToJson(const std::string& normals) const;
};

PatchFitResult FitBernsteinPatch(const std::vector<Eigen::Vector3d>& points,
                                 const std::vector<Eigen::Vector3d>& normals,
                                 const PatchFitOptions& options);

// The default tetrahedron for a cloud (see the header comment).
Tetrahedron EnclosingTetrahedron(const std::vector<Eigen::Vector3d>& points);

}  // namespace implicitfit
