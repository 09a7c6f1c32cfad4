// Fitting a B-spline surface patch to a cloud by orthogonal distance (fit --model
// bspline-surface --grid NUxNV [--degree p]; docs/maths.md TB-3, JE-1's fit of parametric
// surfaces).
//
// Unknowns: the n_u x n_v control points (clamped uniform knots on [0, 1]^2, degree p both ways)
// and one parameter pair (u_k, v_k) per point. Objective: sum_k |x_k - S(u_k, v_k)|^2 plus a
// small smoothing term lambda sum |second differences of the control net|^2 (along u and along
// v; lambda = smoothing x N / (n_u n_v), so it weighs like a fraction of the data per control
// point), which fills parts of the rectangle that hold no data smoothly. The default 1e-5 keeps
// those parts well posed without flattening the data's own shape: at 1e-3 the penalty biased the
// held-out random surfaces of tests/fit/splines/bspline_surface_fit_test.cc to 1.0-1.7 sigma off
// their clean samples (0.08-0.82 sigma at 1e-5) and cost the bunny range scan's freeform stage 8
// points in 100 of its smooth regions.
// 1. Start (fit/splines/parameter_frame.h): (u_k, v_k) from the least-area rectangle of the
//    points projected on their plane; then the control points by linear least squares (the
//    objective is quadratic in them for fixed parameters: sparse normal equations, Cholesky).
// 2. Parameter correction: every point's (u_k, v_k) <- its foot on the current surface
//    (model/splines/closest_point.h), then the linear solve again, while the RMS improves by more
//    than 1% (at most correction_rounds).
// 3. Joint refinement, as bundle adjustment: Ceres over the control points (3-blocks) and the
//    (u_k, v_k) (2-blocks, eliminated first: SPARSE_SCHUR with the point blocks in elimination
//    group 0). Each residual x_k - S(u_k, v_k) depends on the (p + 1)^2 control points of the
//    span holding (u_k, v_k); the parameters are bounded to that span (a residual's blocks are
//    fixed in Ceres), and after each solve every point is projected again and the problem
//    rebuilt (refine_rounds). On at most refine_points points (a regular subsample of larger
//    clouds; the linear steps use every point). The result is kept only if it lowers the RMS.
// 4. Every point's signed distance to the final patch (the bspline_surface node's f) gives the
//    RMS and the residuals; S_u x S_v points to the side of the normals (frame above).
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "fit/common/fit_summary.h"
#include "model/model.h"

namespace implicitfit {

struct SurfaceFitOptions {
  int degree = 3;                // 1..SplineLimits::kMaxDegree
  int count_u = 6, count_v = 6;  // control points per direction (>= degree + 1)
  double smoothing = 1e-5;       // lambda / (N / (n_u n_v)), >= 0
  int correction_rounds = 8;     // step 2
  int refine_rounds = 2;         // step 3 (0: no joint refinement)
  int refine_points = 20000;     // step 3: largest subsample
  int max_iterations = 50;       // Ceres iterations per round
  int num_threads = 0;           // 0: all cores
  bool IsValid(std::string* error) const;
};

struct SurfaceFitResult : FitSummary {
  int degree = 0, count_u = 0, count_v = 0;
  std::vector<double> control_points;  // 3 n_u n_v, P_ij at 3 (i n_v + j)
  std::vector<Eigen::Vector2d> parameters;  // each point's foot (u, v)
  std::vector<double> residuals;            // each point's signed distance to the patch
  double rms = 0.0, initial_rms = 0.0;      // after step 4; after the first linear solve
  double mean_normal_angle_deg = -1.0;      // between S_u x S_v at the feet and the normals
  int correction_rounds = 0, refine_iterations = 0;
  bool refined = false;  // step 3 lowered the RMS and was kept
  Model ToModel() const;
};

SurfaceFitResult FitBSplineSurface(const std::vector<Eigen::Vector3d>& points,
                                   const std::vector<Eigen::Vector3d>& normals,
                                   const SurfaceFitOptions& options);

}  // namespace implicitfit
