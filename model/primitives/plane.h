// Plane: f(x) = (n . x - d) / |n|, the exact signed distance; n points outward (f > 0 side).
// Parameters: [n_x, n_y, n_z, d] (4). n need not be unit; d is the offset along n / |n| only
// when |n| = 1 (the JSON form always stores a unit normal).
#pragma once

#include "model/vec3.h"

namespace implicitfit {

struct PlaneEvaluator {
  static constexpr int kNumParameters = 4;
  template <typename T>
  static T Evaluate(const T* p, const T* x) {
    return (Dot3(p, x) - p[3]) / Norm3(p);
  }
};

}  // namespace implicitfit
