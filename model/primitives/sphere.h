// Sphere: f(x) = |x - c| - r, the exact signed distance (negative inside).
// Parameters: [c_x, c_y, c_z, r] (4).
#pragma once

#include "model/vec3.h"

namespace implicitfit {

struct SphereEvaluator {
  static constexpr int kNumParameters = 4;
  template <typename T>
  static T Evaluate(const T* p, const T* x) {
    T d[3];
    Sub3(x, p, d);
    return Norm3(d) - p[3];
  }
};

}  // namespace implicitfit
