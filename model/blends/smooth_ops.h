// Smooth absolute value, smooth max and the smooth CSG operators of Li & Phillips (eq. 4-6;
// docs/maths.md, "Smooth absolute value, smooth max and CSG"), with the paper's slips corrected.
//
//   mu(t)  = H_n(t / eps)                     (rising range eps, 0 < eps <= delta)
//   g0(t)  = 1 - mu(t + delta),  g1(t) = mu(t + delta) (1 - mu(t - delta)),  g2(t) = mu(t - delta)
//   S_abs(t) = -g0 t + g1 (t^2 / (2 delta) + delta / 2) + g2 t       (= |t| for |t| >= delta + eps)
//   S_max(x, y) = (x + y + S_abs(x - y)) / 2                          (>= max(x, y))
//
// Project sign convention (docs/design.md): f < 0 inside. Hence
//   union(a, b)        = -S_max(-a, -b)   (smooth min)
//   intersection(a, b) =  S_max(a, b)
//   difference(a, b)   =  S_max(a, -b)    (a minus b)
// Order n = 0 is the sharp operator: S_abs = |t|, S_max = max.
#pragma once

#include <cmath>

#include "model/blends/unit_step.h"

namespace implicitfit {

template <typename T>
T SmoothAbs(const T& t, const T& delta, const T& eps, int order) {
  using std::abs;
  if (order == 0) return ValueOf(t) < 0.0 ? T(-t) : t;
  const UnitStep& h = UnitStep::OfOrder(order);
  const T mu_plus = h.WithRisingRange(T(t + delta), eps);
  const T mu_minus = h.WithRisingRange(T(t - delta), eps);
  const T g0 = 1.0 - mu_plus;
  const T g1 = mu_plus * (1.0 - mu_minus);
  const T g2 = mu_minus;
  const T parabola = t * t / (2.0 * delta) + 0.5 * delta;
  return -g0 * t + g1 * parabola + g2 * t;
}

template <typename T>
T SmoothMax(const T& x, const T& y, const T& delta, const T& eps, int order) {
  if (order == 0) return ValueOf(x) >= ValueOf(y) ? x : y;  // exactly max, no rounding
  return 0.5 * (x + y + SmoothAbs(T(x - y), delta, eps, order));
}

template <typename T>
T SmoothUnion(const T& a, const T& b, const T& delta, const T& eps, int order) {
  return -SmoothMax(T(-a), T(-b), delta, eps, order);
}

template <typename T>
T SmoothIntersection(const T& a, const T& b, const T& delta, const T& eps, int order) {
  return SmoothMax(a, b, delta, eps, order);
}

template <typename T>
T SmoothDifference(const T& a, const T& b, const T& delta, const T& eps, int order) {
  return SmoothMax(a, T(-b), delta, eps, order);
}

}  // namespace implicitfit
