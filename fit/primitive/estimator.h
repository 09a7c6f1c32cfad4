// Which criterion the primitive fitter's final parameters satisfy (`fit --estimator`):
//   robust         maximum likelihood on the inliers (trimmed at 3 sigma, fit/primitive/primitive_fitter.h)
//   least-squares  min sum_i d_i^2 over every point, no trimming: the orthogonal-distance
//                  ("Gaussian") association of ISO 10360-6 (fit/metrology/least_squares_fit.h)
//   minimum-zone   min max_i |d_i|: the Chebyshev association, the minimum zone of ISO 1101
//                  form tolerances (fit/metrology/minimum_zone.h)
// d_i is the exact signed orthogonal distance of point i (model/*.h).
#pragma once

#include <string>

namespace implicitfit {

enum class Estimator { kRobust, kLeastSquares, kMinimumZone };

inline const char* EstimatorName(Estimator e) {
  switch (e) {
    case Estimator::kLeastSquares:
      return "least-squares";
    case Estimator::kMinimumZone:
      return "minimum-zone";
    default:
      return "robust";
  }
}

// "robust" | "least-squares" | "minimum-zone" -> the estimator; false for any other name.
inline bool EstimatorFromName(const std::string& name, Estimator* e) {
  for (Estimator k : {Estimator::kRobust, Estimator::kLeastSquares, Estimator::kMinimumZone})
    if (name == EstimatorName(k)) {
      *e = k;
      return true;
    }
  return false;
}

}  // namespace implicitfit
