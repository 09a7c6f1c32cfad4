// Paraboloid of revolution placed by a point and a normal (Li & Phillips §4.1; docs/maths.md LP-2):
// vertex P, outward axis a (any non-zero length, n = a / |a|), curvature kappa at the vertex:
//   u = x - P,  h = n . u = (a . x - a . P) / |a|,  |w|^2 = |u|^2 - h^2 = |a x u|^2 / |a|^2,
//   f = h + (kappa / 2) |w|^2.
// f = 0 is the paraboloid h = -(kappa / 2) |w|^2 through P with normal n there; grad f = n at
// the vertex, |grad f| = sqrt(1 + kappa^2 |w|^2) on the surface (so f is a distance to first
// order only; the fitter's residual f / |grad f| is exact at the vertex).
// kappa > 0: the solid {f <= 0} is convex (the surface bends away from the outward normal);
// kappa = 0: the plane through P with normal n, bit for bit the plane {normal a, offset a . P}
// (h is computed with the plane's own operations); kappa < 0: concave.
// Parameters: [P 3, a 3, kappa 1] (7).
#pragma once

#include "model/vec3.h"

namespace implicitfit {

struct ParaboloidEvaluator {
  static constexpr int kNumParameters = 7;
  template <typename T>
  static T Evaluate(const T* p, const T* x) {
    const T* a = p + 3;
    const T norm = Norm3(a);
    const T h = (Dot3(a, x) - Dot3(a, p)) / norm;
    T u[3], c[3];
    Sub3(x, p, u);
    Cross3(a, u, c);
    const T w2 = Dot3(c, c) / (norm * norm);
    return h + 0.5 * p[6] * w2;
  }
};

}  // namespace implicitfit
