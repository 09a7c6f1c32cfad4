// Standard deviations of a fitted model tree's parameters (flat layout of Model::parameters()).
// Residuals r_i = f(x_i; theta) / |grad f(x_i)| (first-order distance, |grad f| held at the
// solution), Jacobian by central differences in theta, covariance sigma^2 (J^T J)^+ with
// sigma^2 = sum r_i^2 / (N - rank). The pseudo-inverse leaves out the gauge directions (a
// plane's (n, d) scale, an axis's length, a cylinder's point along its axis): parameters
// orthogonal to them (delta, epsilon, radii) get their usual marginal deviations.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "model/model.h"

namespace implicitfit {

std::vector<double> TreeStandardDeviations(const Model& model,
                                           const std::vector<Eigen::Vector3d>& points);

}  // namespace implicitfit
