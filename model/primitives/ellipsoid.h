// Ellipsoid with centre c, semi-axis lengths r_1..r_3 along orthonormal directions e_1..e_3.
// Its exact distance has no closed form, so f is the first-order (Taubin) distance of
//   g(x) = |y| - 1,   y_i = (x - c) . e_i / r_i,      f = g / |grad g|,
//   grad g = sum_i e_i y_i / (r_i |y|),
// which is exact for a sphere (all r_i equal), vanishes exactly on the ellipsoid, has
// |grad f| = 1 there, and keeps f < 0 inside. |grad g| >= 1 / max r_i away from the centre.
// With e_i orthonormal, |grad g|^2 = sum_i (y_i / r_i)^2 / |y|^2, so
//   f = (|y| - 1) |y| / sqrt(sum_i (y_i / r_i)^2).
// At the centre (y = 0) f has no limit (it tends to -r_i along axis i); |y|^2 and the sum are
// floored by tau = 1e-200 and tau * mean_i(1 / r_i^2), so f(centre) = -1 / sqrt(mean 1 / r_i^2),
// a finite value between -max r_i and -min r_i (the old floor of grad g alone gave -1e150 there,
// which a smooth max then cancelled to 0). The floors change nothing for |y| > 1e-90.
// Parameters: [c 3, r 3, e_1 3, e_2 3] (12); e_1 is normalised, e_2 made orthogonal to it
// (Gram-Schmidt) and e_3 = e_1 x e_2 at evaluation, so any non-parallel pair is valid.
#pragma once

#include <cmath>

#include "model/vec3.h"

namespace implicitfit {

struct EllipsoidEvaluator {
  static constexpr int kNumParameters = 12;
  template <typename T>
  static T Evaluate(const T* p, const T* x) {
    using std::sqrt;
    T e[3][3];
    const T inv1 = 1.0 / Norm3(p + 6);
    for (int k = 0; k < 3; ++k) e[0][k] = p[6 + k] * inv1;
    const T proj = Dot3(e[0], p + 9);
    for (int k = 0; k < 3; ++k) e[1][k] = p[9 + k] - proj * e[0][k];
    const T inv2 = 1.0 / Norm3(e[1]);
    for (int k = 0; k < 3; ++k) e[1][k] *= inv2;
    Cross3(e[0], e[1], e[2]);
    T d[3];
    Sub3(x, p, d);
    T y[3];
    for (int i = 0; i < 3; ++i) y[i] = Dot3(d, e[i]) / p[3 + i];
    constexpr double kTau = 1e-200;
    const T ny = sqrt(Dot3(y, y) + kTau);
    T scaled = T(0.0), mean_inverse = T(0.0);
    for (int i = 0; i < 3; ++i) {
      const T inverse = 1.0 / p[3 + i];
      scaled += y[i] * y[i] * inverse * inverse;
      mean_inverse += inverse * inverse;
    }
    return (ny - 1.0) * ny / sqrt(scaled + (kTau / 3.0) * mean_inverse);
  }
};

}  // namespace implicitfit
