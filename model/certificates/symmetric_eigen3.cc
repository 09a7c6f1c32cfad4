#include "model/certificates/symmetric_eigen3.h"

#include <algorithm>
#include <cmath>

namespace implicitfit {
namespace {

inline void Cross(const double* a, const double* b, double* c) {
  c[0] = a[1] * b[2] - a[2] * b[1];
  c[1] = a[2] * b[0] - a[0] * b[2];
  c[2] = a[0] * b[1] - a[1] * b[0];
}
inline double Dot(const double* a, const double* b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

// x^T M y for the symmetric M given as rows.
inline double Form(const double m[3][3], const double* x, const double* y) {
  double s = 0.0;
  for (int i = 0; i < 3; ++i) s += x[i] * Dot(m[i], y);
  return s;
}

// min_only: out[0] only (skips the deflation when the smallest root is the isolated one).
void Eigenvalues(const double a[6], double out[3], bool min_only) {
  double scale = 0.0;
  for (int i = 0; i < 6; ++i) scale = std::max(scale, std::abs(a[i]));
  if (!(scale > 0.0) || !std::isfinite(scale)) {
    // Zero matrix (all eigenvalues 0) or non-finite input (NaN propagates).
    const double v = scale == 0.0 ? 0.0 : std::nan("");
    out[0] = out[1] = out[2] = v;
    return;
  }
  const double inv = 1.0 / scale;
  const double q = (a[0] + a[1] + a[2]) * inv / 3.0;
  // B = A/scale - qI, as full rows.
  double b[3][3] = {{a[0] * inv - q, a[3] * inv, a[4] * inv},
                    {a[3] * inv, a[1] * inv - q, a[5] * inv},
                    {a[4] * inv, a[5] * inv, a[2] * inv - q}};
  const double p2 = (b[0][0] * b[0][0] + b[1][1] * b[1][1] + b[2][2] * b[2][2] +
                     2.0 * (b[0][1] * b[0][1] + b[0][2] * b[0][2] + b[1][2] * b[1][2])) /
                    6.0;
  if (p2 == 0.0) {
    out[0] = out[1] = out[2] = q * scale;
    return;
  }
  const double p = std::sqrt(p2);
  double c01[3];
  Cross(b[0], b[1], c01);
  const double det = Dot(c01, b[2]);  // det(B) as a triple product
  const double r = std::clamp(det / (2.0 * p2 * p), -1.0, 1.0);
  const double phi = std::acos(r) / 3.0;
  constexpr double kTwoThirdsPi = 2.0943951023931954923;
  // Isolated root (shifted): the largest when r >= 0, the smallest when r < 0.
  const double iso = r >= 0.0 ? 2.0 * p * std::cos(phi) : 2.0 * p * std::cos(phi + kTwoThirdsPi);
  if (min_only && r < 0.0) {
    out[0] = (iso + q) * scale;
    return;
  }
  // Its eigenvector: largest cross product of two rows of B - iso I.
  double m[3][3];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) m[i][j] = b[i][j] - (i == j ? iso : 0.0);
  double c[3][3];
  Cross(m[0], m[1], c[0]);
  Cross(m[0], m[2], c[1]);
  Cross(m[1], m[2], c[2]);
  int best = 0;
  double best_norm = Dot(c[0], c[0]);
  for (int i = 1; i < 3; ++i) {
    const double n = Dot(c[i], c[i]);
    if (n > best_norm) best = i, best_norm = n;
  }
  double lo, hi;
  if (best_norm > 0.0) {
    const double s = 1.0 / std::sqrt(best_norm);
    const double v[3] = {c[best][0] * s, c[best][1] * s, c[best][2] * s};
    // u: v x (the axis least aligned with v), w = v x u.
    int axis = 0;
    for (int i = 1; i < 3; ++i)
      if (std::abs(v[i]) < std::abs(v[axis])) axis = i;
    double ax[3] = {0.0, 0.0, 0.0};
    ax[axis] = 1.0;
    double u[3], w[3];
    Cross(v, ax, u);
    const double un = 1.0 / std::sqrt(Dot(u, u));
    for (double& x : u) x *= un;
    Cross(v, u, w);
    const double m00 = Form(b, u, u), m11 = Form(b, w, w), m01 = Form(b, u, w);
    // |entries| <= 1 after scaling: no overflow in the squares.
    const double mean = 0.5 * (m00 + m11);
    const double d = std::sqrt(0.25 * (m00 - m11) * (m00 - m11) + m01 * m01);
    lo = mean - d;
    hi = mean + d;
  } else {
    lo = 2.0 * p * std::cos(phi + 2.0 * kTwoThirdsPi);
    hi = r >= 0.0 ? 2.0 * p * std::cos(phi + kTwoThirdsPi) : 2.0 * p * std::cos(phi);
    if (lo > hi) std::swap(lo, hi);
  }
  double e[3] = {iso, lo, hi};
  if (e[0] > e[1]) std::swap(e[0], e[1]);
  if (e[1] > e[2]) std::swap(e[1], e[2]);
  if (e[0] > e[1]) std::swap(e[0], e[1]);
  out[0] = (e[0] + q) * scale;
  out[1] = (e[1] + q) * scale;
  out[2] = (e[2] + q) * scale;
}

}  // namespace

double SymmetricMinEigenvalue3(const double a[6]) {
  double out[3];
  Eigenvalues(a, out, true);
  return out[0];
}

void SymmetricEigenvalues3(const double a[6], double out[3]) { Eigenvalues(a, out, false); }

}  // namespace implicitfit
