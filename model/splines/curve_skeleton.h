// Curves as skeletons of skeleton_offset tubes (docs/maths.md TB-3, CO-1): the tube of radius r
// around a curve C is f(x) = |x - C(t*)| - r, t* the closest point's parameter
// (model/splines/closest_point.h). Curve kinds (the textbook's curves, placed in space):
//   B-spline / NURBS / Bezier: C(t) = sum w_i N_i(t) P_i / sum w_i N_i(t) (parameters: the P_i);
//   ellipse: C(t) = c + A cos(2 pi t) + B sin(2 pi t), t in [0, 1] (parameters c, A, B: any
//            ellipse, A and B its conjugate semi-diameters; a circle when A, B are orthogonal of
//            equal length);
//   helix:   C(t) = c + A cos(2 pi t) + B sin(2 pi t) + C t, t in [0, turns] (C: the rise per turn);
//   segment: r1 (1 - t) + r2 t is read as the one-segment skeleton (model/primitives/skeleton_offset.h).
// The distance is evaluated on Jets at the double-precision foot t* held fixed: at a foot inside
// the range, d|x - C(t)|/dt = 0 there, and at an end the foot does not move under small changes,
// so the first derivatives in x and in the parameters are exact (the envelope theorem).
#pragma once

#include <cmath>
#include <type_traits>
#include <vector>

#include "model/splines/bspline_evaluation.h"
#include "model/splines/closest_point.h"
#include "model/vec3.h"

namespace implicitfit {

// The number of 3-vectors of a curve kind's parameters (B-spline: its control points).
inline int CurveVectorCount(const SplineStructure& s) {
  if (s.curve == CurveKind::kEllipse) return 3;
  if (s.curve == CurveKind::kHelix) return 4;
  return s.count[0];
}

// out[k] = d^k C / dt^k, k = 0..order (<= 2).
template <typename T>
void CurveKindDerivatives(const SplineStructure& s, const T* p, const T& t, int order,
                          T out[kMaxSplineDerivative + 1][3]) {
  if (s.curve == CurveKind::kBSpline) {
    CurveDerivatives(s, p, t, order, out);
    return;
  }
  using std::cos;
  using std::sin;
  const double w = 2.0 * M_PI;
  const T c = cos(w * t), sn = sin(w * t);
  const bool helix = s.curve == CurveKind::kHelix;
  for (int k = 0; k < 3; ++k) {
    out[0][k] = p[k] + p[3 + k] * c + p[6 + k] * sn;
    if (helix) out[0][k] += p[9 + k] * t;
    if (order >= 1) {
      out[1][k] = w * (p[6 + k] * c - p[3 + k] * sn);
      if (helix) out[1][k] += p[9 + k];
    }
    if (order >= 2) out[2][k] = -(w * w) * (p[3 + k] * c + p[6 + k] * sn);
  }
}

// The distance from x to the curve and its nearest point q (T[3]).
template <typename T>
T CurveSkeletonClosest(const SplineStructure& s, const T* p, const T* x, T* q) {
  const int n = 3 * CurveVectorCount(s);
  double xd[3] = {ValueOf(x[0]), ValueOf(x[1]), ValueOf(x[2])};
  CurveFoot foot;
  if constexpr (std::is_same<T, double>::value) {
    foot = ClosestCurvePoint(s, p, xd);
  } else {
    thread_local std::vector<double> values;
    values.resize(static_cast<size_t>(n));
    for (int i = 0; i < n; ++i) values[i] = ValueOf(p[i]);
    foot = ClosestCurvePoint(s, values.data(), xd);
  }
  T c[kMaxSplineDerivative + 1][3];
  CurveKindDerivatives(s, p, T(foot.t), 0, c);
  T d[3];
  for (int k = 0; k < 3; ++k) {
    q[k] = c[0][k];
    d[k] = x[k] - c[0][k];
  }
  const T d2 = Dot3(d, d);
  using std::sqrt;  // guarded: a Jet's sqrt has no derivative at 0 (x on the curve)
  return ValueOf(d2) > 0.0 ? sqrt(d2) : T(0.0);
}

}  // namespace implicitfit
