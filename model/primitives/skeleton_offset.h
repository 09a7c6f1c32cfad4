// Skeleton offsets (Coleman's offset surfaces in distance form; docs/maths.md CO-1): the union of the
// balls of radius r around a skeleton S made of points, segments or a polyline,
//   f(x) = min_{s in S} d(x, s) - r,
// the exact signed distance of that union (min of exact distances, each |grad| = 1).
//   point p:        d = |x - p|                      (one point: the sphere, same operations)
//   segment [a, b]: d = |x - (a + t (b - a))|,  t = clamp((x - a).(b - a) / |b - a|^2, 0, 1)
//   polyline v_0..v_k: the segments [v_j, v_j+1].
//   triangle (a, b, c): d = |x - q|, q = a + s (b - a) + t (c - a) the projection of x onto the
//                   triangle's plane when s, t >= 0 and s + t <= 1 (n = (b - a) x (c - a),
//                   s = ((x - a) x (c - a)) . n / |n|^2, t = ((b - a) x (x - a)) . n / |n|^2),
//                   else the nearest of its three edges (a surface skeleton, docs/maths.md CO-1).
// One segment is a capsule, a polyline a tube. Jets follow the nearest element (the min picks
// by value; across its switch f is continuous, grad f has a kink on the medial set).
// Parameters: [skeleton points (3 m), r (1)]; segments store their two end points each
// (m = 2 x segments), a polyline its vertices, triangles their three corners each (m = 3 x
// triangles). Closest() also returns the nearest skeleton point: Coleman's features on a
// skeleton (model/primitives/coleman_features.h, docs/maths.md CO-2) need it.
#pragma once

#include <algorithm>
#include <cmath>

#include "model/scalar.h"
#include "model/vec3.h"

namespace implicitfit {

// kCurve: a B-spline, NURBS, ellipse or helix (model/splines/curve_skeleton.h; evaluated by the
// model tree, which holds the curve's structure).
enum class SkeletonKind { kPoints = 0, kSegments = 1, kPolyline = 2, kTriangles = 3, kCurve = 4 };

struct SkeletonOffsetEvaluator {
  // Distance from x to the segment [a, b]; a point when b == a.
  template <typename T>
  static T SegmentDistance(const T* a, const T* b, const T* x) {
    T ab[3], ax[3];
    Sub3(b, a, ab);
    Sub3(x, a, ax);
    const T len2 = Dot3(ab, ab);
    if (!(ValueOf(len2) > 0.0)) return Norm3(ax);
    T t = Dot3(ax, ab) / len2;
    if (ValueOf(t) <= 0.0) return Norm3(ax);
    if (ValueOf(t) >= 1.0) {
      T bx[3];
      Sub3(x, b, bx);
      return Norm3(bx);
    }
    T d[3];
    for (int k = 0; k < 3; ++k) d[k] = ax[k] - t * ab[k];
    return Norm3(d);
  }

  // The point of the segment [a, b] nearest to x (a when b == a).
  template <typename T>
  static void SegmentClosest(const T* a, const T* b, const T* x, T* q) {
    T ab[3], ax[3];
    Sub3(b, a, ab);
    Sub3(x, a, ax);
    const T len2 = Dot3(ab, ab);
    T t = T(0.0);
    if (ValueOf(len2) > 0.0) t = Dot3(ax, ab) / len2;
    if (ValueOf(t) <= 0.0) t = T(0.0);
    if (ValueOf(t) >= 1.0) t = T(1.0);
    for (int k = 0; k < 3; ++k) q[k] = a[k] + t * ab[k];
  }

  // The point of the triangle (a, b, c) nearest to x (formula at the top of the file).
  template <typename T>
  static void TriangleClosest(const T* a, const T* b, const T* c, const T* x, T* q) {
    T ab[3], ac[3], ax[3], n[3];
    Sub3(b, a, ab);
    Sub3(c, a, ac);
    Sub3(x, a, ax);
    Cross3(ab, ac, n);
    const T nn = Dot3(n, n);
    if (ValueOf(nn) > 0.0) {
      T m[3];
      Cross3(ax, ac, m);
      const T s = Dot3(m, n) / nn;
      Cross3(ab, ax, m);
      const T t = Dot3(m, n) / nn;
      if (ValueOf(s) >= 0.0 && ValueOf(t) >= 0.0 && ValueOf(s) + ValueOf(t) <= 1.0) {
        for (int k = 0; k < 3; ++k) q[k] = a[k] + s * ab[k] + t * ac[k];
        return;
      }
    }
    const T* corners[3] = {a, b, c};
    T best2 = T(0.0);
    for (int e = 0; e < 3; ++e) {
      T y[3], d[3];
      SegmentClosest(corners[e], corners[(e + 1) % 3], x, y);
      Sub3(x, y, d);
      const T d2 = Dot3(d, d);
      if (e == 0 || ValueOf(d2) < ValueOf(best2)) {
        best2 = d2;
        for (int k = 0; k < 3; ++k) q[k] = y[k];
      }
    }
  }

  // The distance from x to the skeleton, and its nearest point *q (the first of equals).
  template <typename T>
  static T Closest(SkeletonKind kind, int num_points, const T* p, const T* x, T* q) {
    T best = T(0.0);
    bool first = true;
    auto take = [&](const T* y) {
      T d[3];
      Sub3(x, y, d);
      const T d2 = Dot3(d, d);
      using std::sqrt;  // guarded: a Jet's sqrt has no derivative at 0 (x on the skeleton)
      const T dist = ValueOf(d2) > 0.0 ? sqrt(d2) : T(0.0);
      if (first || ValueOf(dist) < ValueOf(best)) {
        best = dist;
        for (int k = 0; k < 3; ++k) q[k] = y[k];
      }
      first = false;
    };
    if (kind == SkeletonKind::kPoints) {
      for (int i = 0; i < num_points; ++i) take(p + 3 * i);
    } else if (kind == SkeletonKind::kTriangles) {
      for (int i = 0; i + 2 < num_points; i += 3) {
        T y[3];
        TriangleClosest(p + 3 * i, p + 3 * i + 3, p + 3 * i + 6, x, y);
        take(y);
      }
    } else {
      const int step = kind == SkeletonKind::kSegments ? 2 : 1;
      for (int i = 0; i + 1 < num_points; i += step) {
        T y[3];
        SegmentClosest(p + 3 * i, p + 3 * i + 3, x, y);
        take(y);
      }
    }
    return best;
  }

  template <typename T>
  static T Evaluate(SkeletonKind kind, int num_points, const T* p, const T* x) {
    T best = T(0.0);
    bool first = true;
    auto take = [&](const T& d) {
      if (first || ValueOf(d) < ValueOf(best)) best = d;
      first = false;
    };
    if (kind == SkeletonKind::kPoints) {
      for (int i = 0; i < num_points; ++i) {
        T d[3];
        Sub3(x, p + 3 * i, d);
        take(Norm3(d));
      }
    } else if (kind == SkeletonKind::kTriangles) {
      for (int i = 0; i + 2 < num_points; i += 3) {
        T y[3], d[3];
        TriangleClosest(p + 3 * i, p + 3 * i + 3, p + 3 * i + 6, x, y);
        Sub3(x, y, d);
        take(Norm3(d));
      }
    } else {
      const int step = kind == SkeletonKind::kSegments ? 2 : 1;
      for (int i = 0; i + 1 < num_points; i += step)
        take(SegmentDistance(p + 3 * i, p + 3 * i + 3, x));
    }
    return best - p[3 * num_points];
  }
};

}  // namespace implicitfit
