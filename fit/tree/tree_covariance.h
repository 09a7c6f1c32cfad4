// Standard deviations of a fitted model tree's parameters (flat layout of Model::parameters()).
// Residuals r_i = f(x_i; theta) / |grad f(x_i)| (first-order distance, |grad f| held at the
// solution), Jacobian by central differences in theta, covariance sigma^2 (J^T J)^+ with
// sigma^2 = sum r_i^2 / (N - rank). The pseudo-inverse leaves out the gauge directions (a
// plane's (n, d) scale, an axis's length, a cylinder's point along its axis): parameters
// orthogonal to them (delta, epsilon, radii) get their usual marginal deviations.
// `columns` (flat indices, ascending) restricts theta to those parameters, the others held at
// their values (their deviations are reported as 0): a reconstructed solid refits only its
// blends and the primitives below them (fit/reconstruct/solid_reconstruction.h), and the
// Jacobian over every parameter of a tree of 36 primitives (the Kinect milk carton: thousands
// of parameters, each central difference a pass over the whole tree, at 13 000 points) took
// about 10 minutes. FreeParameterColumns gives the fields that no node's "fixed" names.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "model/model.h"

namespace implicitfit {

std::vector<double> TreeStandardDeviations(const Model& model,
                                           const std::vector<Eigen::Vector3d>& points,
                                           const std::vector<int>& columns);
// Every parameter.
std::vector<double> TreeStandardDeviations(const Model& model,
                                           const std::vector<Eigen::Vector3d>& points);

// Flat indices of the parameters of fields that the nodes' "fixed" lists do not name.
std::vector<int> FreeParameterColumns(const Model& model);

}  // namespace implicitfit
