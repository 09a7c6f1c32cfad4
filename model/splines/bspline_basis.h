// B-spline basis functions and their derivatives (docs/maths.md TB-3), templated on the scalar
// of the parameter t (double, Ceres Jets, Dual3) so that a basis evaluated at a point that
// carries derivatives passes them on; the knots are plain numbers (structure, not parameters).
//
// Degree p, n basis functions N_{0..n-1,p} on knots u_0 <= ... <= u_{n+p} (order p + 1).
// Cox-de Boor: N_{i,0} = 1 on [u_i, u_{i+1}), else 0, and
//   N_{i,q}(t) = (t - u_i) / (u_{i+q} - u_i) N_{i,q-1}(t)
//              + (u_{i+q+1} - t) / (u_{i+q+1} - u_{i+1}) N_{i+1,q-1}(t),
// a term with a zero denominator being 0 (its N_{.,q-1} vanishes identically there). On the
// span [u_s, u_{s+1}) only N_{s-p..s} are non-zero; they are computed together by the
// triangular scheme (de Boor; Piegl and Tiller, The NURBS Book, algorithms A2.2 and A2.3 for
// the derivatives), which needs no zero-denominator case on a valid knot vector. The basis sums
// to 1 on [u_p, u_n]; with half-open spans the right end u_n would belong to no span, so the
// span of t = u_n is the last non-empty one (closed on the right): FindSpan.
// CoxDeBoor() is the recursion itself, one function at a time, with either convention for 0/0
// (the textbook's "0/0 := 1" or 0): the reference the tests compare the triangular scheme with.
#pragma once

#include <string>
#include <vector>

#include "model/scalar.h"

namespace implicitfit {

// Largest degree any spline of the model file may have (fixed-size buffers below).
constexpr int kMaxSplineDegree = 10;

// The span s in [p, n - 1] with u_s <= t < u_{s+1} (t clamped to [u_p, u_n]; t = u_n gives the
// last non-empty span). knots: n + p + 1 numbers.
int FindSpan(int degree, int count, const double* knots, double t);

// The p + 1 non-zero basis values N_{span-p..span,p}(t) into N (triangular scheme).
template <typename T>
void BasisFunctions(int span, const T& t, int degree, const double* knots, T* N) {
  T left[kMaxSplineDegree + 1], right[kMaxSplineDegree + 1];
  N[0] = T(1.0);
  for (int j = 1; j <= degree; ++j) {
    left[j] = t - knots[span + 1 - j];
    right[j] = knots[span + j] - t;
    T saved = T(0.0);
    for (int r = 0; r < j; ++r) {
      const T tmp = N[r] / (right[r + 1] + left[j - r]);
      N[r] = saved + right[r + 1] * tmp;
      saved = left[j - r] * tmp;
    }
    N[j] = saved;
  }
}

// Values and derivatives up to order `order` (<= degree) of the p + 1 non-zero basis functions:
// ders[k * (p + 1) + j] = d^k/dt^k N_{span-p+j,p}(t) (Piegl and Tiller A2.3).
template <typename T>
void BasisDerivatives(int span, const T& t, int degree, int order, const double* knots, T* ders) {
  const int p = degree;
  T ndu[kMaxSplineDegree + 1][kMaxSplineDegree + 1];
  T left[kMaxSplineDegree + 1], right[kMaxSplineDegree + 1];
  ndu[0][0] = T(1.0);
  for (int j = 1; j <= p; ++j) {
    left[j] = t - knots[span + 1 - j];
    right[j] = knots[span + j] - t;
    T saved = T(0.0);
    for (int r = 0; r < j; ++r) {
      ndu[j][r] = right[r + 1] + left[j - r];  // lower triangle: knot differences
      const T tmp = ndu[r][j - 1] / ndu[j][r];
      ndu[r][j] = saved + right[r + 1] * tmp;  // upper triangle: basis values
      saved = left[j - r] * tmp;
    }
    ndu[j][j] = saved;
  }
  for (int j = 0; j <= p; ++j) ders[j] = ndu[j][p];
  for (int k = 1; k <= order; ++k)
    for (int j = 0; j <= p; ++j) ders[k * (p + 1) + j] = T(0.0);
  T a[2][kMaxSplineDegree + 1];
  for (int r = 0; r <= p; ++r) {
    int s1 = 0, s2 = 1;
    a[0][0] = T(1.0);
    for (int k = 1; k <= order; ++k) {
      T d = T(0.0);
      const int rk = r - k, pk = p - k;
      if (r >= k) {
        a[s2][0] = a[s1][0] / ndu[pk + 1][rk];
        d = a[s2][0] * ndu[rk][pk];
      }
      const int j1 = rk >= -1 ? 1 : -rk;
      const int j2 = r - 1 <= pk ? k - 1 : p - r;
      for (int j = j1; j <= j2; ++j) {
        a[s2][j] = (a[s1][j] - a[s1][j - 1]) / ndu[pk + 1][rk + j];
        d += a[s2][j] * ndu[rk + j][pk];
      }
      if (r <= pk) {
        a[s2][k] = -a[s1][k - 1] / ndu[pk + 1][r];
        d += a[s2][k] * ndu[r][pk];
      }
      ders[k * (p + 1) + r] = d;
      std::swap(s1, s2);
    }
  }
  double factor = p;
  for (int k = 1; k <= order; ++k) {
    for (int j = 0; j <= p; ++j) ders[k * (p + 1) + j] *= factor;
    factor *= p - k;
  }
}

// The recursion of the header for one function N_{i,p}(t), 0/0 taken as `zero_over_zero`
// (1 or 0: the basis is the same). Spans are half-open except that t = u_n belongs to the last
// non-empty one (as FindSpan). Exponential in p: for tests and small degrees only.
double CoxDeBoor(int i, int degree, double t, const std::vector<double>& knots, int count,
                 double zero_over_zero = 0.0);

// n clamped uniform knots of degree p on [a, b]: p + 1 copies of a, n - p - 1 equally spaced
// interior knots, p + 1 copies of b (n + p + 1 numbers). Requires n >= p + 1.
std::vector<double> ClampedUniformKnots(int degree, int count, double a, double b);

// "" when `knots` is a valid knot vector for n = count functions of degree p (n + p + 1
// finite non-decreasing numbers, u_p < u_n, no knot repeated more than p + 1 times, interior
// knots at most p times), else the problem in words.
std::string KnotVectorProblem(const std::vector<double>& knots, int degree, int count);

// The Greville abscissae (u_{i+1} + ... + u_{i+p}) / p, i = 0..n-1 (degree 0: the span
// midpoints): where basis function i peaks, roughly; the closest-point searches start there.
std::vector<double> GrevilleAbscissae(const std::vector<double>& knots, int degree, int count);

}  // namespace implicitfit
