// Infinite single-nappe circular cone, exact signed distance.
// Apex c, unit axis u = a / |a| pointing from the apex into the opening, half angle alpha in
// (0, pi/2). With h = (x - c) . u and rho = |(x - c) x u| (axial and radial coordinates):
//   f = rho cos(alpha) - h sin(alpha)      where rho sin(alpha) + h cos(alpha) >= 0
//                                           (the nearest surface point is on the nappe)
//   f = sqrt(rho^2 + h^2)                  otherwise (the apex is nearest; always outside)
// Both branches agree in value and gradient on the boundary between them (C^1).
// Parameters: [c 3, a 3, alpha] (7).
#pragma once

#include <cmath>

#include "model/vec3.h"

namespace implicitfit {

struct ConeEvaluator {
  static constexpr int kNumParameters = 7;
  template <typename T>
  static T Evaluate(const T* p, const T* x) {
    using std::cos;
    using std::sin;
    using std::sqrt;
    T rho;
    const T h = AxialCoordinates(p, p + 3, x, &rho);
    const T s = sin(p[6]), c = cos(p[6]);
    if (rho * s + h * c >= 0.0) return rho * c - h * s;
    return sqrt(rho * rho + h * h);
  }
};

}  // namespace implicitfit
