// Least-squares (Gaussian) association of ISO 10360-6 and the form figures the metrology
// estimators report.
//
// Least squares: minimise sum_i d_i(theta)^2 over EVERY point (no trimming), d_i the exact
// signed orthogonal distance (model/*.h). Ceres Levenberg-Marquardt with the closed-form
// derivatives (fit/primitive/primitive_jacobians.h, one residual per point: no compressed normal
// equations, so nothing squares the conditioning), axes on SphereManifold<3>, tolerances at
// the double-precision floor; then Gauss-Newton steps in local coordinates
// (fit/metrology/primitive_tangent.h, column-pivoted QR of the Jacobian), taken while they shrink, until
// one is below 1e-14 of the part size. `final_step` reports the last step's length: the distance to
// the exact least-squares solution, to first order. Computed in a frame centred on the points.
#pragma once

#include <Eigen/Core>
#include <map>
#include <string>
#include <vector>

#include "model/model.h"

namespace implicitfit {

struct FormFigures {
  double rms = 0.0;                               // sqrt(mean d_i^2) over every point
  double min_distance = 0.0, max_distance = 0.0;  // extreme signed distances
  double form_error = 0.0;                        // max - min: width of the zone the fit leaves
};

FormFigures ComputeFormFigures(NodeType kind, const std::vector<double>& params,
                               const std::vector<Eigen::Vector3d>& points);

struct LeastSquaresResult {
  bool success = false;
  std::string message;
  std::vector<double> parameters;  // flat layout of the evaluator, input frame
  FormFigures figures;
  int iterations = 0;       // Ceres iterations plus Gauss-Newton polishing steps
  double final_step = 0.0;  // length of the last Gauss-Newton step (parameter units)
};

// start: a fit close enough to converge (the robust fit); fixed: field name -> kept constant.
LeastSquaresResult LeastSquaresFit(NodeType kind, const std::vector<Eigen::Vector3d>& points,
                                   const std::vector<double>& start,
                                   const std::map<std::string, std::vector<double>>& fixed = {});

}  // namespace implicitfit
