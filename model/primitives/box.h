// Box (textbook Fig. 22.1 block; docs/maths.md TB-1): centre c, rotation R, half sizes h, f the exact
// signed distance
//   y = R^T (x - c),   q_i = |y_i| - h_i,
//   f = |max(q, 0)| + min(max(q_1, q_2, q_3), 0).
// Outside, the first term is the distance to the nearest face, edge or corner; inside, the
// second is minus the distance to the nearest face (the textbook's min form is exact inside
// only). |grad f| = 1 everywhere except on the medial set (kinks), where f is continuous.
// Parameters: [c 3, quaternion (w, x, y, z) 4, h 3] (10). The quaternion is normalised at
// evaluation, so any non-zero 4-vector is a valid rotation; R's columns are the box axes
// e_1, e_2, e_3 (the JSON "axes"). The tree fitter moves it on ceres::QuaternionManifold.
#pragma once

#include <cmath>

#include "model/scalar.h"
#include "model/vec3.h"

namespace implicitfit {

struct BoxEvaluator {
  static constexpr int kNumParameters = 10;

  // Rows of R^T (= the unit box axes e_i) from the quaternion q = (w, x, y, z), normalised.
  template <typename T>
  static void Axes(const T* q, T e[3][3]) {
    const T s = 1.0 / (q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
    const T w = q[0], x = q[1], y = q[2], z = q[3];
    // Column j of R is e_j; R = I + 2 s [ -(y^2+z^2), xy - wz, xz + wy ; ... ].
    e[0][0] = 1.0 - 2.0 * s * (y * y + z * z);
    e[0][1] = 2.0 * s * (x * y + w * z);
    e[0][2] = 2.0 * s * (x * z - w * y);
    e[1][0] = 2.0 * s * (x * y - w * z);
    e[1][1] = 1.0 - 2.0 * s * (x * x + z * z);
    e[1][2] = 2.0 * s * (y * z + w * x);
    e[2][0] = 2.0 * s * (x * z + w * y);
    e[2][1] = 2.0 * s * (y * z - w * x);
    e[2][2] = 1.0 - 2.0 * s * (x * x + y * y);
  }

  template <typename T>
  static T Evaluate(const T* p, const T* x) {
    using std::abs;
    using std::sqrt;
    T e[3][3];
    Axes(p + 3, e);
    T d[3];
    Sub3(x, p, d);
    T q[3];
    for (int i = 0; i < 3; ++i) q[i] = abs(Dot3(e[i], d)) - p[7 + i];
    T outside2 = T(0.0);
    int largest = 0;
    for (int i = 0; i < 3; ++i) {
      if (ValueOf(q[i]) > 0.0) outside2 += q[i] * q[i];
      if (ValueOf(q[i]) > ValueOf(q[largest])) largest = i;
    }
    // Outside: the Euclidean part (sqrt only of a positive sum, so Jets stay finite).
    if (ValueOf(outside2) > 0.0) return sqrt(outside2);
    return q[largest];  // inside or on the boundary: minus the distance to the nearest face
  }
};

}  // namespace implicitfit
