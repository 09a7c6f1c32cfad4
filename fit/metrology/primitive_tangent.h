// Local coordinates of a primitive's parameters, for the fits that need a Jacobian with full
// column rank (the minimum-zone exchange, the point hypotheses' small Gauss-Newton refinement):
//   theta(delta) = Retract(theta, delta),  d_i(theta(delta)) ~ d_i(theta) + g_i . delta,
//   g_i = (d d_i / d theta) B,  B = TangentBasis(theta)  (P x k, k = FreeParameterCount).
// Unit directions (plane normal, axes) move in their tangent plane (two orthonormal vectors
// orthogonal to the direction, then renormalised); the cylinder's axis point moves only
// orthogonally to its axis (sliding along the axis changes nothing: that gauge is removed);
// positions, radii and the cone angle move freely. k = plane 3, sphere 4, cylinder 5, cone 6,
// torus 7: the number of parameters that shape the surface, so a primitive through k points in
// general position is determined up to finitely many solutions.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "model/model.h"

namespace implicitfit {

int FreeParameterCount(NodeType kind);

Eigen::MatrixXd TangentBasis(NodeType kind, const std::vector<double>& params);

// params += B delta, directions renormalised (B = TangentBasis(kind, params) before the move).
void Retract(NodeType kind, const Eigen::MatrixXd& basis, const Eigen::VectorXd& delta,
             std::vector<double>* params);

// The exact signed distance d(x) (fit/primitive/primitive_jacobians.h) and, when dp is given, its
// derivative with respect to the flat parameters (P values).
double PrimitiveSignedDistance(NodeType kind, const double* params, const double* x, double* dp);

}  // namespace implicitfit

namespace implicitfit {

// The primitive moved by +shift (positions shifted, the plane's offset adjusted).
void TranslatePrimitive(NodeType kind, const Eigen::Vector3d& shift, std::vector<double>* params);

}  // namespace implicitfit
