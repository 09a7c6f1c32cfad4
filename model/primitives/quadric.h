// General quadric q(x) = x^T A x + 2 b^T x + c, with A symmetric, stored as the ten numbers
// [a11 a22 a33 a12 a13 a23 b1 b2 b3 c] (the Fit4CAD convention). The solid is {q <= 0}, so
// f < 0 inside agrees with the project's sign. f is the first-order (Taubin) distance
//   f = q / |grad q|,   grad q = 2 (A x + b),
// which vanishes exactly on the zero set and has |grad f| = 1 there. Where grad q = 0 (the
// centre of a central quadric, or a singular point such as a cone's apex) the denominator is
// floored (sqrt(|grad q|^2 + 1e-300)) so f stays finite and differentiable instead of NaN.
// Parameters: the ten coefficients (10). Scaling all of them by s > 0 does not change f.
#pragma once

#include <cmath>

#include "model/vec3.h"

namespace implicitfit {

struct QuadricEvaluator {
  static constexpr int kNumParameters = 10;
  template <typename T>
  static T Evaluate(const T* p, const T* x) {
    using std::sqrt;
    // A x + b
    T g[3];
    g[0] = p[0] * x[0] + p[3] * x[1] + p[4] * x[2] + p[6];
    g[1] = p[3] * x[0] + p[1] * x[1] + p[5] * x[2] + p[7];
    g[2] = p[4] * x[0] + p[5] * x[1] + p[2] * x[2] + p[8];
    // x^T A x + 2 b^T x + c = x . (A x + b) + b . x + c
    const T q = Dot3(x, g) + p[6] * x[0] + p[7] * x[1] + p[8] * x[2] + p[9];
    return q / (2.0 * sqrt(Dot3(g, g) + 1e-300));
  }
};

}  // namespace implicitfit
