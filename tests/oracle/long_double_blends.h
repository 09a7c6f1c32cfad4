// Long double references for the smooth operators of model/blends (test oracle only, no code
// shared with model/): H_n by the literal recursion of Li & Phillips' eq. 2-3, S_abs and S_max
// by eq. 4-6 (the README's corrections), the convexity-preserving S^c_abs by Gauss-Legendre
// quadrature of H_n on each of its polynomial pieces (exact for degree n <= 14 with 8 nodes),
// all in long double.
//
// Magnitudes. The formula (x + y + S_abs(x - y)) / 2 loses the smaller argument when
// |x| >> |y| even in long double (1e17 against 1e-15 needs 107 bits). The identity
// S_max(x, y) = c + S_max(x - c, y - c) holds for every real c (it is the formula itself:
// (x + y) / 2 shifts by c, x - y does not), so the reference evaluates the formula in the frame
// translated by c = max(x, y) (computed in long double): the larger argument becomes 0 exactly
// and the formula's sum no longer cancels.
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

namespace oracle {

using LD = long double;

inline LD FL(int n, LD s) {
  if (n == 0) return s < 0 ? 0.0L : (s > 0 ? 1.0L : 0.5L);
  return s / n * FL(n - 1, s) + (1.0L - s / n) * FL(n - 1, s - 1.0L);
}

inline LD HL(int n, LD t) {
  if (n == 0) return FL(0, t);
  if (t <= -1) return 0.0L;
  if (t >= 1) return 1.0L;
  return FL(n, n * (t + 1.0L) / 2.0L);
}

// Eq. 5 (f = t^2 / (2 delta) + delta / 2), mu(t) = H_n(t / eps).
inline LD SAbsL(LD t, LD delta, LD eps, int n) {
  if (n == 0) return std::fabs(t);
  const LD mp = HL(n, (t + delta) / eps), mm = HL(n, (t - delta) / eps);
  return -(1.0L - mp) * t + mp * (1.0L - mm) * (t * t / (2.0L * delta) + delta / 2.0L) + mm * t;
}

// Gauss-Legendre nodes and weights on [-1, 1] (Newton on P_m, long double).
inline void GaussLegendre(int m, std::vector<LD>* x, std::vector<LD>* w) {
  x->assign(m, 0.0L);
  w->assign(m, 0.0L);
  const LD pi = 3.141592653589793238462643383279502884L;
  for (int i = 0; i < m; ++i) {
    LD z = std::cos(pi * (i + 0.75L) / (m + 0.5L)), dp = 0;
    for (int it = 0; it < 100; ++it) {
      LD p0 = 1, p1 = z;
      for (int k = 2; k <= m; ++k) {
        const LD p2 = ((2 * k - 1) * z * p1 - (k - 1) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      dp = m * (z * p1 - p0) / (z * z - 1);
      const LD dz = p1 / dp;
      z -= dz;
      if (std::fabs(dz) < 1e-19L) break;
    }
    (*x)[i] = z;
    (*w)[i] = 2 / ((1 - z * z) * dp * dp);
  }
}

// integral_{-1}^{u} H_n(r) dr: H_n is a polynomial of degree n on each interval where
// s = n (r + 1) / 2 lies between two integers; 8 Gauss nodes per interval are exact there.
inline LD IntegralHL(int n, LD u) {
  if (u <= -1) return 0.0L;
  static const std::vector<LD> gx = [] {
    std::vector<LD> x, w;
    GaussLegendre(8, &x, &w);
    return x;
  }();
  static const std::vector<LD> gw = [] {
    std::vector<LD> x, w;
    GaussLegendre(8, &x, &w);
    return w;
  }();
  LD sum = 0;
  const LD end = std::min<LD>(u, 1.0L);
  for (int j = 0; j < n; ++j) {
    const LD a = -1.0L + 2.0L * j / n, b = std::min<LD>(-1.0L + 2.0L * (j + 1) / n, end);
    if (b <= a) break;
    for (int q = 0; q < 8; ++q) sum += (b - a) / 2 * gw[q] * HL(n, (a + b) / 2 + (b - a) / 2 * gx[q]);
  }
  if (u > 1) sum += u - 1;  // H_n = 1 beyond 1
  return sum;
}

// S^c_abs(t) = -t + 2 w integral_{-1}^{t / w} H_n.
inline LD ConvexSAbsL(LD t, LD w, int n) {
  if (n == 0) return std::fabs(t);
  if (t >= w) return t;
  if (t <= -w) return -t;
  return -t + 2 * w * IntegralHL(n, t / w);
}

// S_max by eq. 6 in the frame translated by c = max(x, y) (see the top of the file).
inline LD SMaxL(LD x, LD y, LD delta, LD eps, int n) {
  const LD c = std::max(x, y), a = x - c, b = y - c;
  return c + (a + b + SAbsL(a - b, delta, eps, n)) / 2.0L;
}

inline LD ConvexSMaxL(LD x, LD y, LD w, int n) {
  const LD c = std::max(x, y), a = x - c, b = y - c;
  return c + (a + b + ConvexSAbsL(a - b, w, n)) / 2.0L;
}

}  // namespace oracle
