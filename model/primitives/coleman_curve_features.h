// Coleman's curve features (docs/maths.md CO-2, curve features): a feature along a polyline
// f_0..f_n drawn on the isosurface (e.g. a surface cord, model/primitives/surface_cord.h) instead
// of at one point. Its core curve is the polyline of the vertices' closest core points
// c_v = c(f_v), with u_v = (f_v - c_v) / |f_v - c_v| (the core's normal there). The feature
// distance of x is measured to that curve, projected on the core, in the two ways of the point
// feature:
//   p1: q1 = the point of the core curve nearest to x, u = the normalised linear interpolation of
//       the u_v at q1; d1 = |(x - q1) - ((x - q1) . u) u| (x projected onto the plane through q1
//       normal to u: the feature's sides follow the normal at the curve);
//   p2: q2 = the point of the core curve nearest to c(x); d2 = |c(x) - q2| (sides follow the core);
//   k = s(phi d2 + (1 - phi) d1; W, W + R), j = s(d; R_C + D + W, R_C + D + W + R),
//   g = k j + (1 - k) i, combined with the point features by the maximum (as Coleman keeps the
//   largest sub-surface value). One vertex is the point feature (q1 = c_f, u = u_f).
// Closed form (core z <= 0, a straight curve above the x axis): within |y| <= W of it the zero
// set is z = R_C + D + W + R/2, beyond |y| >= W + R it is z = R_C / 2, for any flare.
// Parameters of a curve feature: [3 n vertices, W, D, R, phi].
#pragma once

#include <cmath>
#include <vector>

#include "model/primitives/coleman_features.h"

namespace implicitfit {

struct ColemanCurveFeatures {
  // The nearest point of the polyline v (3 n numbers) to y: its index of segment and fraction.
  template <typename T>
  static void NearestOnPolyline(const std::vector<T>& v, const T* y, int* segment, T* lambda) {
    const int n = static_cast<int>(v.size() / 3);
    double best = INFINITY;
    *segment = 0;
    *lambda = T(0.0);
    for (int s = 0; s + 1 < n || (n == 1 && s == 0); ++s) {
      const T* a = v.data() + 3 * s;
      const T* b = n == 1 ? a : a + 3;
      T ab[3], ay[3];
      for (int k = 0; k < 3; ++k) {
        ab[k] = b[k] - a[k];
        ay[k] = y[k] - a[k];
      }
      const T len2 = ab[0] * ab[0] + ab[1] * ab[1] + ab[2] * ab[2];
      T t = ValueOf(len2) > 0.0 ? (ay[0] * ab[0] + ay[1] * ab[1] + ay[2] * ab[2]) / len2 : T(0.0);
      if (ValueOf(t) < 0.0) t = T(0.0);
      if (ValueOf(t) > 1.0) t = T(1.0);
      double d2 = 0.0;
      for (int k = 0; k < 3; ++k) {
        const double e = ValueOf(ay[k]) - ValueOf(t) * ValueOf(ab[k]);
        d2 += e * e;
      }
      if (d2 < best) {
        best = d2;
        *segment = s;
        *lambda = t;
      }
      if (n == 1) break;
    }
  }

  // The coleman_features node with curve features: f_points = the point features' value
  // (ColemanFeatures::Evaluate, 1/2 - max(i, g_f)), core(y) the child's signed distance; the
  // curve features' g join the maximum: f = 1/2 - max(1/2 - f_points, max_curves g).
  template <typename T, typename Core>
  static T Evaluate(const std::vector<int>& vertices, const T& rc, const T* q, const T* x,
                    const T& f_points, const Core& core) {
    const T d = ColemanFeatures::Clamped(core(x));
    const T i = ColemanFeatures::Falloff(d, T(0.0), rc);
    auto closest = [&](const T* y, T* c, T* n) { ColemanFeatures::ClosestCorePoint(y, core, c, n); };
    return 0.5 - Field(vertices, q, rc, x, d, i, 0.5 - f_points, closest);
  }

  // max over the curve features of g (header); `field` is the value to beat (i and the point
  // features). vertices[f]: the vertex count of feature f; q: its parameters, one after another.
  template <typename T, typename ClosestPoint>
  static T Field(const std::vector<int>& vertices, const T* q, const T& rc, const T* x, const T& d,
                 const T& i, T field, const ClosestPoint& closest) {
    for (int count : vertices) {
      const T &w = q[3 * count], &depth = q[3 * count + 1], &r = q[3 * count + 2],
              &flare = q[3 * count + 3];
      std::vector<T> core(3 * static_cast<size_t>(count)), normal(3 * static_cast<size_t>(count));
      for (int v = 0; v < count; ++v) closest(q + 3 * v, &core[3 * v], &normal[3 * v]);
      int seg;
      T lambda;
      NearestOnPolyline(core, x, &seg, &lambda);
      const int b = count == 1 ? seg : seg + 1;
      T q1[3], u[3];
      for (int k = 0; k < 3; ++k) {
        q1[k] = core[3 * seg + k] + lambda * (core[3 * b + k] - core[3 * seg + k]);
        u[k] = (1.0 - lambda) * normal[3 * seg + k] + lambda * normal[3 * b + k];
      }
      const T un = Length(u);
      for (int k = 0; k < 3; ++k) u[k] = ValueOf(un) > 0.0 ? u[k] / un : T(k == 2 ? 1.0 : 0.0);
      T along = T(0.0);
      for (int k = 0; k < 3; ++k) along += (x[k] - q1[k]) * u[k];
      T d1[3];
      for (int k = 0; k < 3; ++k) d1[k] = x[k] - q1[k] - along * u[k];
      T mixed = Length(d1);
      if (ValueOf(flare) != 0.0) {
        T cx[3], unused[3];
        closest(x, cx, unused);
        NearestOnPolyline(core, cx, &seg, &lambda);
        const int b2 = count == 1 ? seg : seg + 1;
        T d2[3];
        for (int k = 0; k < 3; ++k)
          d2[k] = cx[k] - (core[3 * seg + k] + lambda * (core[3 * b2 + k] - core[3 * seg + k]));
        mixed = flare * Length(d2) + (1.0 - flare) * mixed;
      }
      const T kx = ColemanFeatures::Falloff(mixed, w, w + r);
      const T raised = rc + depth + w;
      const T j = ColemanFeatures::Falloff(d, raised, raised + r);
      const T g = kx * j + (1.0 - kx) * i;
      if (ValueOf(g) > ValueOf(field)) field = g;
      q += 3 * count + 4;
    }
    return field;
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
