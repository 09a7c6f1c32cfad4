// A certified convex patch on the subspace of Guo's shape constraints (b = N y, orthonormal
// N; fit/bernstein/patch_shape_constraints.h), close to a given certified convex patch b0 off
// it: the start of a convex fit under shape constraints (fit/bernstein/convex_patch_fit.h).
//
// 1. Affine correction. Every A^mu is a second difference of the control points, so adding the
//    control points of an affine function (degree 1 elevated to k: b_lambda = sum_i lambda_i g_i
//    / k, g_i its values at the vertices) changes none of them. g is the least-squares solution
//    of (I - N N^T)(b0 - E g) = 0 (E: the 4 affine columns); when the residual vanishes, b0 - E g
//    lies on the subspace with exactly b0's certificate. That succeeds whenever the affine
//    functions have the freedom: through-vertices (1 condition each) and vertex normals (3
//    conditions, one free scale each) with 2 x normals + through-vertices <= 4.
// 2. Otherwise, Kelley's cutting planes on the concave phi(y) = min_mu lambda_min(A^mu(N y)):
//    maximise t subject to t <= v^T A^mu(N y) v for the collected (mu, v) (each the minimiser at
//    an earlier iterate: a supporting hyperplane of phi, since A^mu is linear in b) and
//    -1 <= (N y)_j <= 1, a linear programme (GLPK). The LP optimum bounds max phi over that box
//    from above, and since phi is homogeneous that is the largest relative margin
//    phi / max |b| on the subspace: when it falls below `margin`, no certified patch satisfies
//    the constraints (e.g. through an edge, where the largest is 0). It stops once
//    phi(y) >= 10 margin max |N y| (or after 300 cuts, undecided). The start is then the convex combination (1 - a) N N^T b0 + a N y
//    with the smallest a (bisection, 30 halvings) whose relative margin is at least `margin`
//    (phi is concave, so every a beyond the first certified one stays certified).
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

namespace implicitfit {

bool ConvexStartOnSubspace(int k, const std::vector<double>& b0, const Eigen::MatrixXd& basis,
                           double margin, std::vector<double>* start, std::string* why);

}  // namespace implicitfit
