// General quadric q(x) = x^T A x + 2 b^T x + c, with A symmetric, stored as the ten numbers
// [a11 a22 a33 a12 a13 a23 b1 b2 b3 c] (the Fit4CAD convention). The solid is {q <= 0}, so
// f < 0 inside agrees with the project's sign. Outside (q >= 0) f is the first-order (Taubin)
// distance
//   f = q / |grad q|,   grad q = 2 (A x + b),
// which vanishes exactly on the zero set and has |grad f| = 1 there. Inside (q < 0) the
// Taubin distance grows without bound near a point where grad q = 0 (the centre of a central
// quadric: -r^2 / (2 |x - centre|) for a sphere), so f is the root of the quadratic model of q
// along the gradient line, q - |grad q| s + a s^2 = 0 at the smaller root s = -f:
//   f = 2 q / (|grad q| + sqrt(|grad q|^2 - 4 a q)),   a = |A|_F / sqrt(3)
// (the discriminant is >= |grad q|^2 since q < 0 <= a). It has the same value and gradient as
// the Taubin distance on the zero set (so the two pieces join C^1 at q = 0), is the exact
// distance inside a sphere (A = s I gives f = |x - centre| - r), and is finite everywhere:
// -sqrt(-q / a) where grad q = 0 (the centre of an ellipsoid lies between -max r_i and
// -min r_i). |grad q| is floored (sqrt(|grad q|^2 + 1e-300)) so f stays differentiable.
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
    const T grad_norm = 2.0 * sqrt(Dot3(g, g) + 1e-300);
    if (!(ValueOf(q) < 0.0)) return q / grad_norm;
    const T a = sqrt((p[0] * p[0] + p[1] * p[1] + p[2] * p[2] +
                      2.0 * (p[3] * p[3] + p[4] * p[4] + p[5] * p[5])) / 3.0 + 1e-300);
    return 2.0 * q / (grad_norm + sqrt(grad_norm * grad_norm - 4.0 * a * q));
  }
};

}  // namespace implicitfit
