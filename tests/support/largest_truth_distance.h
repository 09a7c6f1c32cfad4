// The largest first-order distance |f| / |grad f| of a model over noise-free truth points: the
// solid tests' accuracy figure (compared with 3 sigma of the sampling noise).
#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <vector>

#include "model/model.h"

namespace implicitfit {

inline double LargestTruthDistance(const Model& m, const std::vector<Eigen::Vector3d>& truth) {
  double largest = 0;
  for (const Eigen::Vector3d& x : truth) {
    double f;
    const Eigen::Vector3d g = m.Gradient(x, &f);
    largest = std::max(largest, std::abs(f) / g.norm());
  }
  return largest;
}

}  // namespace implicitfit
