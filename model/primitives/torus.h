// Torus, exact signed distance: with centre c, unit axis u = a / |a|, h = (x - c) . u and
// rho = |(x - c) x u|,   f = sqrt((rho - R)^2 + h^2) - r   (R major, r minor radius).
// Parameters: [c 3, a 3, R, r] (8).
#pragma once

#include <cmath>

#include "model/vec3.h"

namespace implicitfit {

struct TorusEvaluator {
  static constexpr int kNumParameters = 8;
  template <typename T>
  static T Evaluate(const T* p, const T* x) {
    using std::sqrt;
    T rho;
    const T h = AxialCoordinates(p, p + 3, x, &rho);
    const T q = rho - p[6];
    return sqrt(q * q + h * h) - p[7];
  }
};

}  // namespace implicitfit
