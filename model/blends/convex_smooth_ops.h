// Convexity-preserving smooth absolute value and smooth max (docs/maths.md LP-4 b), the
// alternative to Li & Phillips' S_abs (model/blends/smooth_ops.h), which is neither convex nor monotone.
//
//   S^c_abs(t) = -t + 2 * integral_{-inf}^{t} mu_w(s) ds,   mu_w(s) = H_n(s / w),  w > 0
//   S^c_max(x, y) = (x + y + S^c_abs(x - y)) / 2
//
// Properties: S^c_abs'' = 2 mu_w' >= 0 (convex), S^c_abs' = 2 mu_w - 1 in [-1, 1] (1-Lipschitz),
// S^c_abs(t) = |t| for |t| >= w (the integral of H_n over [-1, 1] is 1 by symmetry), C^n, and a
// piecewise polynomial of degree n + 1. Hence S^c_max is convex and nondecreasing in both
// arguments, so a smooth intersection of convex functions is convex. S^c_abs(0) = (2w/n) E|S_n -
// n/2| with S_n Irwin-Hall(n): w/2 for n = 1, 13w/48 for n = 3.
//
// Evaluation. With u = t / w in (-1, 1), s = n (u + 1) / 2, piece j = floor(s), v = s - j:
//   integral_{-1}^{u} H_n = (2/n) (sum_{i<j} integral_0^1 P_i + integral_0^v P_j),
// P_j the exact pieces of model/blends/unit_step.h; every piece is integrated term by term
// (c_i / (i + 1)), the completed areas are summed once per order. Outside (-w, w) the result is
// exactly -t or t. Order 0 is the sharp |t| and max. Templated on the scalar (Ceres Jets, Dual3);
// w is a parameter like delta of the Li-Phillips blend.
//
// S^c_max is evaluated as max(x, y) + (S^c_abs(t) - |t|) / 2 with t = x - y (the same function,
// since (x + y) / 2 = max - |t| / 2): exactly max(x, y) for |t| >= w, and inside the band the
// correction comes from t alone, so the smaller argument is never lost to cancellation.
// CSG in the project sign (f < 0 inside): union = -S^c_max(-a, -b), intersection = S^c_max(a, b),
// difference = S^c_max(a, -b).
#pragma once

#include <cmath>
#include <vector>

#include "model/scalar.h"
#include "model/blends/unit_step.h"

namespace implicitfit {

// The integrated pieces of H_n, one table per order (built once, thread-safe).
class IntegratedUnitStep {
 public:
  static const IntegratedUnitStep& OfOrder(int order);

  int order() const { return order_; }
  // Coefficients of integral_0^v P_j, lowest degree first (constant term 0), in v = s - j.
  const std::vector<double>& piece(int j) const { return pieces_[j]; }
  // sum_{i<j} integral_0^1 P_i.
  double area_before(int j) const { return areas_[j]; }

  // integral_{-1}^{u} H_n(r) dr for u in [-1, 1] (clamped there).
  template <typename T>
  T operator()(const T& u) const {
    const double uv = ValueOf(u);
    if (uv <= -1.0) return T(0.0);
    const T s = 0.5 * double(order_) * (u + 1.0);
    int j = static_cast<int>(std::floor(ValueOf(s)));
    if (j < 0) j = 0;
    if (j > order_ - 1) j = order_ - 1;
    const T v = s - double(j);
    const std::vector<double>& c = pieces_[j];
    T result = T(c.back());
    for (int i = static_cast<int>(c.size()) - 2; i >= 0; --i) result = result * v + c[i];
    return (2.0 / double(order_)) * (result + areas_[j]);
  }

 private:
  explicit IntegratedUnitStep(int order);
  int order_;
  std::vector<std::vector<double>> pieces_;
  std::vector<double> areas_;
};

template <typename T>
T ConvexSmoothAbs(const T& t, const T& w, int order) {
  const double tv = ValueOf(t), wv = ValueOf(w);
  if (order == 0 || tv >= wv) return tv < 0.0 ? T(-t) : t;
  if (tv <= -wv) return T(-t);
  const IntegratedUnitStep& integral = IntegratedUnitStep::OfOrder(order);
  return -t + 2.0 * w * integral(T(t / w));
}

template <typename T>
T ConvexSmoothMax(const T& x, const T& y, const T& w, int order) {
  const bool x_larger = ValueOf(x) >= ValueOf(y);
  const T t = x - y;
  if (order == 0 || std::abs(ValueOf(t)) >= ValueOf(w)) return x_larger ? x : y;
  const T abs_t = x_larger ? t : T(-t);
  return (x_larger ? x : y) + 0.5 * (ConvexSmoothAbs(t, w, order) - abs_t);
}

template <typename T>
T ConvexSmoothUnion(const T& a, const T& b, const T& w, int order) {
  return -ConvexSmoothMax(T(-a), T(-b), w, order);
}

template <typename T>
T ConvexSmoothIntersection(const T& a, const T& b, const T& w, int order) {
  return ConvexSmoothMax(a, b, w, order);
}

template <typename T>
T ConvexSmoothDifference(const T& a, const T& b, const T& w, int order) {
  return ConvexSmoothMax(a, T(-b), w, order);
}

}  // namespace implicitfit
