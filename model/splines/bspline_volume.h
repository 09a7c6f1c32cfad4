// The bspline_volume node (docs/maths.md TB-3): a trivariate tensor-product B-spline implicit
// over a box [x0, x1] x [y0, y1] x [z0, z1] split into n_x x n_y x n_z equal cells,
//   f(x) = sum_{i,j,k} c_ijk N_i(x) N_j(y) N_k(z),
// degree k on clamped uniform knots per axis ((n_a + k) functions along axis a), so f is a
// polynomial of degree k per variable on every cell, C^(k-1) across cells, and linear in the
// coefficients c (x fastest: c_ijk at i + (n_x + k) (j + (n_y + k) k)). Outside the box,
// f(x) = f(pi(x)) + |x - pi(x)| with pi the nearest point of the box: continuous, and positive
// beyond a box whose faces are outside (f > 0 there), so no zero set leaves the box.
#pragma once

#include "model/splines/spline_structure.h"

namespace implicitfit {

struct BSplineVolumeEvaluator {
  template <typename T>
  static T Evaluate(const SplineStructure& s, const T* c, const T* x) {
    const int k = s.degree[0];
    T y[3];
    T outside2 = T(0.0);
    for (int a = 0; a < 3; ++a) {
      const double lo = s.box[a], hi = s.box[3 + a];
      if (ValueOf(x[a]) < lo) {
        y[a] = T(lo);
        outside2 += (x[a] - lo) * (x[a] - lo);
      } else if (ValueOf(x[a]) > hi) {
        y[a] = T(hi);
        outside2 += (x[a] - hi) * (x[a] - hi);
      } else {
        y[a] = x[a];
      }
    }
    T basis[3][kMaxSplineDegree + 1];
    int span[3];
    for (int a = 0; a < 3; ++a) {
      span[a] = FindSpan(k, s.count[a], s.knots[a].data(), ValueOf(y[a]));
      BasisFunctions(span[a], y[a], k, s.knots[a].data(), basis[a]);
    }
    const int nx = s.count[0], ny = s.count[1];
    T f = T(0.0);
    for (int r = 0; r <= k; ++r) {
      const int kk = span[2] - k + r;
      for (int q = 0; q <= k; ++q) {
        const int jj = span[1] - k + q;
        const T* row = c + nx * (jj + ny * kk) + span[0] - k;
        T line = T(0.0);
        for (int i = 0; i <= k; ++i) line += basis[0][i] * row[i];
        f += basis[2][r] * basis[1][q] * line;
      }
    }
    if (ValueOf(outside2) > 0.0) {
      using std::sqrt;
      f += sqrt(outside2);
    }
    return f;
  }
};

}  // namespace implicitfit
