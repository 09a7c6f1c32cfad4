// Skeleton offsets (Coleman's offset surfaces in distance form; NOTES.md CO-1): the union of the
// balls of radius r around a skeleton S made of points, segments or a polyline,
//   f(x) = min_{s in S} d(x, s) - r,
// the exact signed distance of that union (min of exact distances, each |grad| = 1).
//   point p:        d = |x - p|                      (one point: the sphere, same operations)
//   segment [a, b]: d = |x - (a + t (b - a))|,  t = clamp((x - a).(b - a) / |b - a|^2, 0, 1)
//   polyline v_0..v_k: the segments [v_j, v_j+1].
// One segment is a capsule, a polyline a tube. Jets follow the nearest element (the min picks
// by value; across its switch f is continuous, grad f has a kink on the medial set).
// Parameters: [skeleton points (3 m), r (1)]; segments store their two end points each
// (m = 2 x segments), a polyline its vertices.
#pragma once

#include <algorithm>

#include "model/scalar.h"
#include "model/vec3.h"

namespace implicitfit {

enum class SkeletonKind { kPoints = 0, kSegments = 1, kPolyline = 2 };

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
    } else {
      const int step = kind == SkeletonKind::kSegments ? 2 : 1;
      for (int i = 0; i + 1 < num_points; i += step)
        take(SegmentDistance(p + 3 * i, p + 3 * i + 3, x));
    }
    return best - p[3 * num_points];
  }
};

}  // namespace implicitfit
