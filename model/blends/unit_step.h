// Piecewise-polynomial smooth unit step functions of Li & Phillips (eq. 2-3, Def. 2; docs/maths.md,
// "Smooth unit steps").
//   f_0 = Heaviside (f_0(0) = 1/2),  f_n(s) = s/n f_{n-1}(s) + (1 - s/n) f_{n-1}(s - 1),
//   H_n(t) = f_n(n (t + 1) / 2),      mu_eps(t) = H_n(t / eps).
//
// H_n is 0 for t <= -1, 1 for t >= 1, nondecreasing, C^(n-1), and H_n(-t) = 1 - H_n(t).
// On [-1, 1] it is a piecewise polynomial of degree n with n pieces (one per unit interval of
// s = n (t + 1) / 2). The pieces are derived once per order by running the recursion on
// polynomials with exact rational coefficients, then rounded to double and evaluated by Horner
// in the local variable u = s - j in [0, 1): O(n) per call instead of the 2^n calls of the
// recursion.
#pragma once

#include <cmath>
#include <vector>

#include "model/scalar.h"

namespace implicitfit {

class UnitStep {
 public:
  // Largest order whose exact rational pieces are representable without overflow.
  static constexpr int kMaxOrder = 14;

  // The shared table of order n (0 <= n <= kMaxOrder); built once, thread-safe.
  static const UnitStep& OfOrder(int order);

  int order() const { return order_; }

  // Coefficients of piece j (0 <= j < order) in u = s - j, lowest degree first.
  const std::vector<double>& piece(int j) const { return pieces_[j]; }

  // H_n(t).
  template <typename T>
  T operator()(const T& t) const {
    const double tv = ValueOf(t);
    if (order_ == 0) return T(tv < 0.0 ? 0.0 : (tv > 0.0 ? 1.0 : 0.5));
    if (tv <= -1.0) return T(0.0);
    if (tv >= 1.0) return T(1.0);
    const T s = 0.5 * double(order_) * (t + 1.0);
    int j = static_cast<int>(std::floor(ValueOf(s)));
    if (j < 0) j = 0;
    if (j > order_ - 1) j = order_ - 1;
    const T u = s - double(j);
    const std::vector<double>& c = pieces_[j];
    T result = T(c.back());
    for (int i = static_cast<int>(c.size()) - 2; i >= 0; --i) result = result * u + c[i];
    return result;
  }

  // mu_eps(t) = H_n(t / eps), the step with rising range eps > 0.
  template <typename T>
  T WithRisingRange(const T& t, const T& eps) const {
    return (*this)(t / eps);
  }

 private:
  explicit UnitStep(int order);
  int order_;
  std::vector<std::vector<double>> pieces_;
};

}  // namespace implicitfit
