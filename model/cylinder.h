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
    const T inv = 1.0 / Norm3(p + 3);
    const T u[3] = {p[3] * inv, p[4] * inv, p[5] * inv};
    T d[3], radial;
    Sub3(x, p, d);
    AxialRadial(u, d, &radial);
    return radial - p[6];
  }
};

}  // namespace implicitfit
