// The last stage of the primitive fitter: the criterion of options.estimator (fit/primitive/estimator.h)
// applied to every point, started from the robust fit.
//   robust         parameters unchanged; result->form over every point
//   least-squares  fit/metrology/least_squares_fit.h from the robust fit
//   minimum-zone   fit/metrology/minimum_zone.h from the least-squares fit
// On failure result->success is false with the reason (the robust parameters are kept).
#pragma once

#include <Eigen/Core>
#include <vector>

#include "fit/primitive/primitive_fitter.h"

namespace implicitfit {

void FinishWithEstimator(const std::vector<Eigen::Vector3d>& points,
                         const PrimitiveFitOptions& options, PrimitiveFitResult* result);

}  // namespace implicitfit
