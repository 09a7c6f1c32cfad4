#include "fit/primitive/estimator_stage.h"

#include <chrono>

namespace implicitfit {

void FinishWithEstimator(const std::vector<Eigen::Vector3d>& points,
                         const PrimitiveFitOptions& options, PrimitiveFitResult* result) {
  result->estimator = options.estimator;
  if (!result->success || result->parameters.empty()) return;
  const auto start = std::chrono::steady_clock::now();
  const NodeType kind = options.kind;
  if (options.estimator == Estimator::kRobust) {
    result->form = ComputeFormFigures(kind, result->parameters, points);
    return;
  }
  if (options.estimator == Estimator::kMinimumZone && !options.fixed.empty()) {
    result->success = false;
    result->message = "fixed parameters are not available with the minimum-zone estimator";
    return;
  }
  const LeastSquaresResult ls = LeastSquaresFit(kind, points, result->parameters, options.fixed);
  if (!ls.success) {
    result->success = false;
    result->message = ls.message;
    return;
  }
  result->iterations += ls.iterations;
  result->final_step = ls.final_step;
  result->parameters = ls.parameters;
  result->form = ls.figures;
  result->message = ls.message;
  if (options.estimator == Estimator::kMinimumZone) {
    result->zone = MinimumZoneFit(kind, points, ls.parameters);
    result->message = result->zone.message;
    if (!result->zone.success) {
      result->success = false;
    } else {
      result->parameters = result->zone.parameters;
      result->form = result->zone.figures;
    }
  }
  // Every point takes part: inliers and the residual figures are those of all points.
  result->inliers.resize(points.size());
  for (size_t i = 0; i < points.size(); ++i) result->inliers[i] = static_cast<int>(i);
  result->rms = result->form.rms;
  result->max_abs =
      std::max(std::abs(result->form.min_distance), std::abs(result->form.max_distance));
  result->standard_deviations.clear();  // the robust fit's, not valid for this estimator
  result->seconds +=
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace implicitfit
