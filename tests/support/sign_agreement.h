// The sign test of the reconstruction issue: the share of random points of the box [lo, hi]
// where a model's sign agrees with the truth's (f < 0 inside). Points within `away` of the truth's
// zero set (first-order distance |f| / |grad f|) or rejected by `keep` are redrawn, until `count`
// points are tested.
#pragma once

#include <cmath>
#include <functional>
#include <random>

#include "model/model.h"

namespace testsupport {

inline double SignAgreement(const implicitfit::Model& truth, const implicitfit::Model& model,
                            const Eigen::Vector3d& lo, const Eigen::Vector3d& hi, double away,
                            unsigned seed,
                            const std::function<bool(const Eigen::Vector3d&)>& keep = {},
                            int count = 20000) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0, 1);
  int tested = 0, agree = 0;
  while (tested < count) {
    Eigen::Vector3d x;
    for (int k = 0; k < 3; ++k) x[k] = lo[k] + u(rng) * (hi[k] - lo[k]);
    double f;
    const Eigen::Vector3d g = truth.Gradient(x, &f);
    if (std::abs(f) / g.norm() <= away || (keep && !keep(x))) continue;
    ++tested;
    agree += (f < 0) == (model.Value(x) < 0);
  }
  return static_cast<double>(agree) / tested;
}

}  // namespace testsupport
