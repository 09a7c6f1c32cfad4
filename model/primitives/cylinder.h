// Infinite circular cylinder: f(x) = |(x - q) x u| - r with u = a / |a|, the exact signed
// distance (distance to the axis line minus the radius; negative inside).
// Parameters: [q (point on the axis) 3, a (axis direction) 3, r] (7).
#pragma once

#include "model/vec3.h"

namespace implicitfit {

struct CylinderEvaluator {
  static constexpr int kNumParameters = 7;
  template <typename T>
  static T Evaluate(const T* p, const T* x) {
    T radial;
    AxialCoordinates(p, p + 3, x, &radial);
    return radial - p[6];
  }
};

}  // namespace implicitfit
