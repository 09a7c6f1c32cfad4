// Small, fast refits of one primitive to a few hundred or thousand points, used thousands of
// times while the detector grows candidate regions (fit/detect/primitive_detector.h).
//
// Maths: Levenberg-Marquardt on the orthogonal distances f(x_i; p) (every primitive's f is an
// exact signed distance), with the closed-form parameter gradients of fit/primitive/primitive_jacobians.h:
//   (J^T J + lambda diag(J^T J)) delta = -J^T r,   J_ij = df(x_i)/dp_j,
// the step kept when it lowers sum r^2 (lambda / 10), else lambda * 10. Directions (plane normal,
// axes) are over-parametrised 3-vectors; the damping removes their scale null space and they are
// renormalised after each step (the plane's offset with its normal).
// Why not Ceres here: the final maximum-likelihood refinement is Ceres' (fit/primitive/primitive_fitter.h,
// with covariance); these inner refits are tiny dense problems where setting up a Ceres problem
// costs more than solving the 4..7-unknown normal equations directly.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "model/model.h"

namespace implicitfit {

// Refits *params (flat layout of the kind's evaluator) to points[indices]; returns the RMS
// distance after the fit, or a negative value when the fit is degenerate (params unchanged).
double RefitPrimitiveLocally(NodeType kind, const std::vector<Eigen::Vector3d>& points,
                             const std::vector<int>& indices, std::vector<double>* params,
                             int iterations = 8);

}  // namespace implicitfit
