// Points and derivatives of B-spline and NURBS curves and tensor-product surfaces
// (docs/maths.md TB-3), templated on the scalar (double, Jets, Dual3).
//   curve    C(t)    = sum_i w_i N_i(t) P_i / sum_i w_i N_i(t)
//   surface  S(u, v) = sum_ij w_ij N_i(u) M_j(v) P_ij / sum_ij w_ij N_i(u) M_j(v)
// with all w = 1 for plain B-splines (then the denominator is 1 by the partition of unity and is
// not formed). Rational derivatives from the homogeneous ones A = sum w N P, W = sum w N by the
// Leibniz rule (Piegl and Tiller A4.2, A4.4):
//   C^(k) = (A^(k) - sum_{i=1..k} C(k, i) W^(i) C^(k-i)) / W,
//   S^(k,l) = (A^(k,l) - sum_{j=1..l} C(l,j) W^(0,j) S^(k,l-j) - sum_{i=1..k} C(k,i) W^(i,0) S^(k-i,l)
//              - sum_{i=1..k} sum_{j=1..l} C(k,i) C(l,j) W^(i,j) S^(k-i,l-j)) / W.
// Control points: 3 numbers each; a surface's point P_ij (i along u, j along v) at
// 3 (i n_v + j). Only the (p + 1)(q + 1) points of the span are read.
#pragma once

#include "model/splines/spline_structure.h"

namespace implicitfit {

constexpr int kMaxSplineDerivative = 2;

// out[k][c] = d^k C / dt^k, k = 0..order (<= 2), c = x, y, z.
template <typename T>
void CurveDerivatives(const SplineStructure& s, const T* points, const T& t, int order,
                      T out[kMaxSplineDerivative + 1][3]) {
  const int p = s.degree[0];
  const int span = FindSpan(p, s.count[0], s.knots[0].data(), ValueOf(t));
  T ders[(kMaxSplineDerivative + 1) * (kMaxSplineDegree + 1)];
  const int d = order < p ? order : p;
  BasisDerivatives(span, t, p, d, s.knots[0].data(), ders);
  T a[kMaxSplineDerivative + 1][4];
  for (int k = 0; k <= order; ++k)
    for (int c = 0; c < 4; ++c) a[k][c] = T(0.0);
  for (int k = 0; k <= d; ++k)
    for (int j = 0; j <= p; ++j) {
      const int i = span - p + j;
      const double w = s.weight(i);
      const T b = ders[k * (p + 1) + j] * w;
      for (int c = 0; c < 3; ++c) a[k][c] += b * points[3 * i + c];
      a[k][3] += b;
    }
  if (!s.rational()) {
    for (int k = 0; k <= order; ++k)
      for (int c = 0; c < 3; ++c) out[k][c] = a[k][c];
    return;
  }
  static const double binomial[3][3] = {{1, 0, 0}, {1, 1, 0}, {1, 2, 1}};
  for (int k = 0; k <= order; ++k)
    for (int c = 0; c < 3; ++c) {
      T v = a[k][c];
      for (int i = 1; i <= k; ++i) v -= binomial[k][i] * a[i][3] * out[k - i][c];
      out[k][c] = v / a[0][3];
    }
}

// out[k][l][c] = d^(k+l) S / du^k dv^l for k + l <= order (<= 2); other entries are unset.
template <typename T>
void SurfaceDerivatives(const SplineStructure& s, const T* points, const T& u, const T& v,
                        int order, T out[kMaxSplineDerivative + 1][kMaxSplineDerivative + 1][3]) {
  const int p = s.degree[0], q = s.degree[1], nv = s.count[1];
  const int su = FindSpan(p, s.count[0], s.knots[0].data(), ValueOf(u));
  const int sv = FindSpan(q, nv, s.knots[1].data(), ValueOf(v));
  T du[(kMaxSplineDerivative + 1) * (kMaxSplineDegree + 1)];
  T dv[(kMaxSplineDerivative + 1) * (kMaxSplineDegree + 1)];
  const int ou = order < p ? order : p, ov = order < q ? order : q;
  BasisDerivatives(su, u, p, ou, s.knots[0].data(), du);
  BasisDerivatives(sv, v, q, ov, s.knots[1].data(), dv);
  T a[kMaxSplineDerivative + 1][kMaxSplineDerivative + 1][4];
  for (int k = 0; k <= order; ++k)
    for (int l = 0; k + l <= order; ++l)
      for (int c = 0; c < 4; ++c) a[k][l][c] = T(0.0);
  for (int k = 0; k <= ou; ++k)
    for (int l = 0; l <= ov && k + l <= order; ++l)
      for (int i = 0; i <= p; ++i) {
        const T bu = du[k * (p + 1) + i];
        for (int j = 0; j <= q; ++j) {
          const int index = (su - p + i) * nv + (sv - q + j);
          const T b = bu * dv[l * (q + 1) + j] * s.weight(index);
          for (int c = 0; c < 3; ++c) a[k][l][c] += b * points[3 * index + c];
          a[k][l][3] += b;
        }
      }
  if (!s.rational()) {
    for (int k = 0; k <= order; ++k)
      for (int l = 0; k + l <= order; ++l)
        for (int c = 0; c < 3; ++c) out[k][l][c] = a[k][l][c];
    return;
  }
  static const double binomial[3][3] = {{1, 0, 0}, {1, 1, 0}, {1, 2, 1}};
  for (int k = 0; k <= order; ++k)
    for (int l = 0; k + l <= order; ++l)
      for (int c = 0; c < 3; ++c) {
        T v2 = a[k][l][c];
        for (int j = 1; j <= l; ++j) v2 -= binomial[l][j] * a[0][j][3] * out[k][l - j][c];
        for (int i = 1; i <= k; ++i) {
          v2 -= binomial[k][i] * a[i][0][3] * out[k - i][l][c];
          for (int j = 1; j <= l; ++j)
            v2 -= binomial[k][i] * binomial[l][j] * a[i][j][3] * out[k - i][l - j][c];
        }
        out[k][l][c] = v2 / a[0][0][3];
      }
}

}  // namespace implicitfit
