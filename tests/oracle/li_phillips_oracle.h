// An independent, deliberately naive implementation of the papers' formulas, used only as a
// test oracle. It shares no code with model/: H_n by the literal recursion of eq. 2-3 (2^n
// calls), S_abs/S_max by eq. 4-6 with docs/maths.md's corrections, primitives by their textbook
// closed forms written out longhand in double.
#pragma once

#include <algorithm>
#include <cmath>

namespace oracle {

// f_n of eq. 2, straight recursion; f_0 = Heaviside with f_0(0) = 1/2.
inline double F(int n, double s) {
  if (n == 0) return s < 0 ? 0.0 : (s > 0 ? 1.0 : 0.5);
  return s / n * F(n - 1, s) + (1.0 - s / n) * F(n - 1, s - 1.0);
}

// H_n(t) = f_n(n (t + 1) / 2), eq. 3; H_0 is the Heaviside step itself.
inline double H(int n, double t) {
  if (n == 0) return F(0, t);
  return F(n, n * (t + 1.0) / 2.0);
}

inline double Mu(int n, double eps, double t) { return H(n, t / eps); }

// Eq. 5 with f(t) = t^2/(2 delta) + delta/2 (eq. 4 corrected).
inline double SAbs(double t, double delta, double eps, int n) {
  if (n == 0) return std::fabs(t);
  const double g0 = 1.0 - Mu(n, eps, t + delta);
  const double g1 = Mu(n, eps, t + delta) * (1.0 - Mu(n, eps, t - delta));
  const double g2 = Mu(n, eps, t - delta);
  return -g0 * t + g1 * (t * t / (2.0 * delta) + delta / 2.0) + g2 * t;
}

// Eq. 6 corrected: S_max = (x + y + S_abs(x - y)) / 2.
inline double SMax(double x, double y, double delta, double eps, int n) {
  return (x + y + SAbs(x - y, delta, eps, n)) / 2.0;
}

// Li & Phillips' operators are stated for F >= 0 inside. With F = -f (project: f < 0 inside):
// union F = S_max(FA, FB)  ->  f = -S_max(-fa, -fb)
// intersection F = -S_max(-FA, -FB) -> f = S_max(fa, fb)
// subtraction F = -S_max(-FA, FB)   -> f = S_max(fa, -fb)
inline double Union(double fa, double fb, double d, double e, int n) {
  const double FA = -fa, FB = -fb;
  return -SMax(FA, FB, d, e, n);
}
inline double Intersection(double fa, double fb, double d, double e, int n) {
  const double FA = -fa, FB = -fb;
  return -(-SMax(-FA, -FB, d, e, n));
}
inline double Difference(double fa, double fb, double d, double e, int n) {
  const double FA = -fa, FB = -fb;
  return -(-SMax(-FA, FB, d, e, n));
}

inline double Sphere(const double c[3], double r, const double x[3]) {
  return std::sqrt((x[0] - c[0]) * (x[0] - c[0]) + (x[1] - c[1]) * (x[1] - c[1]) +
                   (x[2] - c[2]) * (x[2] - c[2])) -
         r;
}

inline double Plane(const double n[3], double d, const double x[3]) {
  const double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  return (n[0] * x[0] + n[1] * x[1] + n[2] * x[2] - d) / len;
}

}  // namespace oracle
