// The root of a model's f along z at (x, y) in [lo, hi], by bisection to 1e-15 (the tests of
// closed-form zero sets); fails the test unless f(lo) < 0 < f(hi).
#pragma once

#include <gtest/gtest.h>

#include "model/model.h"

namespace testsupport {

inline double RootAlongZ(const implicitfit::Model& m, double x, double y, double lo, double hi) {
  using Vec = Eigen::Vector3d;
  EXPECT_LT(m.Value(Vec(x, y, lo)), 0.0);
  EXPECT_GT(m.Value(Vec(x, y, hi)), 0.0);
  for (int it = 0; it < 200 && hi - lo > 1e-15; ++it) {
    const double mid = 0.5 * (lo + hi);
    (m.Value(Vec(x, y, mid)) < 0 ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

}  // namespace testsupport
