#include "model/blends/unit_step.h"

#include <array>
#include <memory>
#include <stdexcept>
#include <string>

namespace implicitfit {
namespace {

// Exact rational p/q with q > 0, reduced. 128-bit so that the coefficients of orders up to
// UnitStep::kMaxOrder (numerators ~ n^n, denominators ~ n! 2^n) never overflow.
struct Rational {
  __int128 p = 0, q = 1;

  static __int128 Gcd(__int128 a, __int128 b) {
    if (a < 0) a = -a;
    if (b < 0) b = -b;
    while (b != 0) {
      const __int128 r = a % b;
      a = b;
      b = r;
    }
    return a == 0 ? 1 : a;
  }
  static Rational Make(__int128 p, __int128 q) {
    if (q < 0) p = -p, q = -q;
    const __int128 g = Gcd(p, q);
    return Rational{p / g, q / g};
  }
  Rational operator+(const Rational& o) const { return Make(p * o.q + o.p * q, q * o.q); }
  Rational operator*(const Rational& o) const {
    const __int128 g1 = Gcd(p, o.q), g2 = Gcd(o.p, q);
    return Make((p / g1) * (o.p / g2), (q / g2) * (o.q / g1));
  }
  double ToDouble() const { return static_cast<double>(static_cast<long double>(p) / q); }
};

using Poly = std::vector<Rational>;  // coefficients, lowest degree first

Poly Add(const Poly& a, const Poly& b) {
  Poly r(std::max(a.size(), b.size()));
  for (size_t i = 0; i < a.size(); ++i) r[i] = r[i] + a[i];
  for (size_t i = 0; i < b.size(); ++i) r[i] = r[i] + b[i];
  return r;
}

// p(x) * (c0 + c1 x)
Poly MulLinear(const Poly& a, Rational c0, Rational c1) {
  Poly r(a.size() + 1);
  for (size_t i = 0; i < a.size(); ++i) {
    r[i] = r[i] + a[i] * c0;
    r[i + 1] = r[i + 1] + a[i] * c1;
  }
  return r;
}

// p(x + h) by repeated synthetic (Taylor) shifts.
Poly Shift(Poly a, __int128 h) {
  const Rational rh = Rational::Make(h, 1);
  const int n = static_cast<int>(a.size());
  for (int i = 0; i < n; ++i)
    for (int k = n - 2; k >= i; --k) a[k] = a[k] + a[k + 1] * rh;
  return a;
}

}  // namespace

UnitStep::UnitStep(int order) : order_(order) {
  // Pieces of f_m in the global variable s: piece j lives on [j, j+1); f_m = 0 left of 0 and
  // 1 right of m. Start from f_0 (no interior piece) and run the recursion of eq. 2.
  std::vector<Poly> f;  // pieces of f_{m-1}
  for (int m = 1; m <= order; ++m) {
    std::vector<Poly> g(m);
    const Rational inv_m = Rational::Make(1, m);
    const Rational minus_inv_m = Rational::Make(-1, m);
    for (int j = 0; j < m; ++j) {
      // s/m * f_{m-1}(s) on [j, j+1)
      const Poly left = (j <= m - 2) ? f[j] : Poly{Rational::Make(1, 1)};
      Poly term1 = MulLinear(left, Rational{}, inv_m);
      // (1 - s/m) * f_{m-1}(s - 1): s - 1 lies in [j-1, j)
      Poly term2;
      if (j >= 1) {
        const Poly shifted = (j - 1 <= m - 2) ? Shift(f[j - 1], -1) : Poly{Rational::Make(1, 1)};
        term2 = MulLinear(shifted, Rational::Make(1, 1), minus_inv_m);
      }
      g[j] = Add(term1, term2);
    }
    f = std::move(g);
  }
  pieces_.resize(order);
  for (int j = 0; j < order; ++j) {
    const Poly local = Shift(f[j], j);  // in u = s - j
    pieces_[j].resize(local.size());
    for (size_t i = 0; i < local.size(); ++i) pieces_[j][i] = local[i].ToDouble();
  }
}

const UnitStep& UnitStep::OfOrder(int order) {
  if (order < 0 || order > kMaxOrder)
    throw std::invalid_argument("smooth unit step order " + std::to_string(order) +
                                " is outside 0.." + std::to_string(kMaxOrder));
  static const std::array<std::unique_ptr<UnitStep>, kMaxOrder + 1> table = [] {
    std::array<std::unique_ptr<UnitStep>, kMaxOrder + 1> t;
    for (int n = 0; n <= kMaxOrder; ++n) t[n].reset(new UnitStep(n));
    return t;
  }();
  return *table[order];
}

}  // namespace implicitfit
