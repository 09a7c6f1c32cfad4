// Conversions between Cartesian quadrics and Bernstein control points on a tetrahedron, and
// degree elevation. Used to build patches from known shapes and as test oracles.
//
// Maths. Write a quadric q(x) = x^T A x + 2 b^T x + c in homogeneous form q = X^T G X,
// X = (x, 1), G = [[A, b], [b^T, c]]. Its blossom is Q(x, y) = X^T G Y, and the degree-2
// control points are the blossom at the vertices: b_{e_i+e_j} = Q(x_i, x_j) = (X^T G X)_ij with
// X = [X1 X2 X3 X4] (vertices in homogeneous coordinates, one per column).
// Back: f(tau) = tau^T Bm tau with Bm_ij = b_{e_i+e_j}, and tau = X^-1 (x, 1), so
// G = X^-T Bm X^-1.
// Degree elevation k -> k+1 (same polynomial):
//   b'_lambda = sum_{i: lambda_i >= 1} lambda_i / (k+1) * b_{lambda - e_i},  |lambda| = k+1.
// Re-expression on another tetrahedron S (subdivision, extension): with a_i the barycentric
// coordinates of S's vertex i with respect to T, the control points of the same polynomial on S
// are the blossom values b^S_lambda = p[a_1 (lambda_1 times), ..., a_4 (lambda_4 times)],
// computed by k de Casteljau steps each at its own point (exact zeros stay exact: a face of S on
// a face of T gives rows with no weight off that face).
#pragma once

#include <Eigen/Core>
#include <vector>

#include "model/bernstein/bernstein_patch.h"

namespace implicitfit {

struct CartesianQuadric {
  Eigen::Matrix3d A = Eigen::Matrix3d::Zero();  // symmetric
  Eigen::Vector3d b = Eigen::Vector3d::Zero();
  double c = 0.0;
  double operator()(const Eigen::Vector3d& x) const { return x.dot(A * x) + 2.0 * b.dot(x) + c; }
};

// Control points (docs/design.md order) of q on tet, at degree k >= 2 (elevated from 2).
std::vector<double> QuadricToBernstein(const CartesianQuadric& q, const Tetrahedron& tet,
                                       int k = 2);
// The quadric of a degree-2 patch (10 control points).
CartesianQuadric BernsteinToQuadric(const double* control_points, const Tetrahedron& tet);
// The same polynomial at degree k + 1.
std::vector<double> ElevateDegree(int k, const std::vector<double>& control_points);
// M with b^S = M b^T (n x n, n = NumBernsteinControlPoints(k)); row i of `a`: the barycentric
// coordinates of S's vertex i in T (any real numbers summing to 1: S need not lie in T).
Eigen::MatrixXd ReexpressionMatrix(int k, const Eigen::Matrix4d& a);

}  // namespace implicitfit
