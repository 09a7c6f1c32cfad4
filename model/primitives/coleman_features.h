// Coleman's feature-based shaping (docs/maths.md CO-2, the paper's slips corrected), project
// sign. The one child's f is a signed distance to the core C (plane, sphere, skeleton_offset,
// ...); d(x) = max(f(x), 0) and c(x) = x - d(x) grad d(x) its closest core point (grad by central
// differences of the child, step 1e-6 (1 + |x|)). With the falloff (App. A, one cubic piece, C^1)
//   s(t; a, b) = 1 (t <= a),  0 (t >= b),  1 - (3u^2 - 2u^3) between, u = (t - a) / (b - a):
//   i(x) = s(d(x); 0, R_C)                                   the offset field, iso 1/2
//   per feature (point f, width W, depth D, radius R, flare phi in [0, 1]):
//     c_f = c(f), u = (f - c_f) / |f - c_f|   (the core's normal at f when f is on the core)
//     p1(x) = x - ((x - c_f) . u) u             (onto the plane through c_f normal to u)
//     p2(x) = c(x)                              (the closest core point)
//     k(x) = s(phi |p2 - c_f| + (1 - phi) |p1 - c_f|; W, W + R)   (flare mixes the distances)
//     j(x) = s(d(x); R_C + D + W, R_C + D + W + R)                  (the raised core; printed form)
//     g_f(x) = k j + (1 - k) i
//   field = max(i, max_f g_f),   f(x) = 1/2 - field   (< 0 inside, where the field is > 1/2).
// Closed form (core z <= 0, a feature above the origin): the zero set is z = R_C + D + W + R/2
// within rho <= W of the axis and z = R_C / 2 beyond rho >= W + R, whatever the flare (p1 = p2).
// f is flat (zero gradient) inside the core's plateau and beyond the falloff: the fitter's
// residual f / |grad f| is floored there (fit/tree/tree_point_residual.h).
// Parameters: [R_C, then per feature: f (3), W, D, R, phi] (1 + 7 m).
// Two JSON forms: docs/maths.md CO-2's, features on a skeleton_offset node in field mode (R_C = its
// "radius", the core its skeleton, c(x) the exact nearest skeleton point: EvaluateOnCore), and
// the project's coleman_features node over one child that is a signed distance to a solid core
// (a half-space, a sphere, ...: Evaluate, c(x) by central differences of the child). On the same
// core the two agree; the closed-form plateau holds for both.
#pragma once

#include <algorithm>
#include <cmath>

#include "model/scalar.h"

namespace implicitfit {

struct ColemanFeatures {
  static constexpr int kPerFeature = 7;

  // s(t; a, b) of Coleman's App. A.
  template <typename T>
  static T Falloff(const T& t, const T& a, const T& b) {
    if (ValueOf(t) <= ValueOf(a)) return T(1.0);
    if (ValueOf(t) >= ValueOf(b)) return T(0.0);
    const T u = (t - a) / (b - a);
    return 1.0 - u * u * (3.0 - 2.0 * u);
  }

  // core(y): the child's signed distance at y (T[3]); d = max(core, 0), the closest core point
  // by central differences of the core (see above).
  template <typename T, typename Core>
  static T Evaluate(int count, const T* p, const T* x, const Core& core) {
    return EvaluateOnCore(
        count, p, x, [&](const T* y) { return Clamped(core(y)); },
        [&](const T* y, T* c, T* n) { ClosestCorePoint(y, core, c, n); });
  }

  // The same field over a core given by distance(y) = d(y) >= 0 and closest(y, c, n), which
  // sets c = c(y) and n = the unit direction from c(y) to y. A skeleton_offset node with
  // "features" (docs/maths.md CO-2's JSON form) passes its skeleton's exact nearest point
  // (model/primitives/skeleton_offset.h), so no numerical differentiation is involved there.
  template <typename T, typename Distance, typename ClosestPoint>
  static T EvaluateOnCore(int count, const T* p, const T* x, const Distance& distance,
                          const ClosestPoint& closest) {
    const T rc = p[0];
    const T d = distance(x);
    const T i = Falloff(d, T(0.0), rc);
    T field = i;
    for (int q = 0; q < count; ++q) {
      const T* e = p + 1 + kPerFeature * q;
      const T &w = e[3], &depth = e[4], &r = e[5], &flare = e[6];
      T cf[3], u[3];
      closest(e, cf, u);
      T along = T(0.0);
      for (int k = 0; k < 3; ++k) along += (x[k] - cf[k]) * u[k];
      T d1[3];
      for (int k = 0; k < 3; ++k) d1[k] = x[k] - along * u[k] - cf[k];
      T mixed = Length(d1);
      if (ValueOf(flare) != 0.0) {
        T cx[3], unused[3], d2[3];
        closest(x, cx, unused);
        for (int k = 0; k < 3; ++k) d2[k] = cx[k] - cf[k];
        mixed = flare * Length(d2) + (1.0 - flare) * mixed;
      }
      const T kx = Falloff(mixed, w, w + r);
      const T raised = rc + depth + w;
      const T j = Falloff(d, raised, raised + r);
      const T g = kx * j + (1.0 - kx) * i;
      if (ValueOf(g) > ValueOf(field)) field = g;
    }
    return 0.5 - field;
  }

  // Unit direction from c to y, or +z when y == c (a feature point on the core itself: its
  // direction is undefined; docs/maths.md CO-2 puts feature points on the isosurface, d > 0).
  template <typename T>
  static void DirectionFrom(const T* c, const T* y, T* n) {
    T v[3] = {y[0] - c[0], y[1] - c[1], y[2] - c[2]};
    const T len = Length(v);
    for (int k = 0; k < 3; ++k) n[k] = ValueOf(len) > 0.0 ? v[k] / len : T(k == 2 ? 1.0 : 0.0);
  }

  template <typename T>
  static T Clamped(const T& v) {
    return ValueOf(v) > 0.0 ? v : T(0.0);
  }
  // c(y) = y - d(y) grad d(y); *n = the unit direction from c(y) to y, or the core's gradient
  // direction when y is on or in the core.
  template <typename T, typename Core>
  static void ClosestCorePoint(const T* y, const Core& core, T* c, T* n) {
    double scale = 1.0;
    for (int k = 0; k < 3; ++k) scale = std::max(scale, std::abs(ValueOf(y[k])));
    const double h = 1e-6 * scale;
    T grad[3];
    for (int k = 0; k < 3; ++k) {
      T yp[3] = {y[0], y[1], y[2]}, ym[3] = {y[0], y[1], y[2]};
      yp[k] += h;
      ym[k] -= h;
      grad[k] = (core(yp) - core(ym)) / (2.0 * h);
    }
    const T len = Length(grad);
    for (int k = 0; k < 3; ++k) n[k] = ValueOf(len) > 0.0 ? grad[k] / len : T(k == 2 ? 1.0 : 0.0);
    const T d = Clamped(core(y));
    for (int k = 0; k < 3; ++k) c[k] = y[k] - d * n[k];
  }

 private:
  template <typename T>
  static T Length(const T* v) {
    const T s = v[0] * v[0] + v[1] * v[1] + v[2] * v[2];
    using std::sqrt;
    return ValueOf(s) > 0.0 ? sqrt(s) : T(0.0);
  }
};

}  // namespace implicitfit
