// Regression record (docs/maths.md LP-4 a): Li & Phillips' smooth max S_max is neither
// convex nor monotone, so a "li-phillips" smooth intersection of convex solids is NOT convex.
// No code may rely on it; the convexity-preserving blend is "smoothing": "convex"
// (model/blends/convex_smooth_ops.h). Expected values are docs/maths.md's (independent NumPy scripts).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "model/model.h"
#include "model/blends/smooth_ops.h"

namespace implicitfit {
namespace {

// The witness tree: intersection of the half-planes x <= 0 and y <= 0, order 3, delta = eps = 1.
Model WitnessTree() {
  Model m;
  const int a = m.AddPrimitive(NodeType::kPlane, {1, 0, 0, 0});
  const int b = m.AddPrimitive(NodeType::kPlane, {0, 1, 0, 0});
  m.AddOperator(NodeType::kIntersection, {a, b}, 1.0, 1.0, 3);
  return m;
}

// The y of the zero set at a given x, by bisection on [-1, 1] (f(x, -1) < 0 < f(x, 1)).
double ZeroAt(const Model& m, double x) {
  double lo = -1.0, hi = 1.0;
  EXPECT_LT(m.Value(Eigen::Vector3d(x, lo, 0)), 0.0);
  EXPECT_GT(m.Value(Eigen::Vector3d(x, hi, 0)), 0.0);
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    (m.Value(Eigen::Vector3d(x, mid, 0)) < 0.0 ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

TEST(LiPhillipsSmoothMax, WitnessMidpointOfTwoZeroSetPointsLiesOutside) {
  const Model m = WitnessTree();
  const double y1 = ZeroAt(m, -1.890), y2 = ZeroAt(m, -0.990);
  EXPECT_NEAR(y1, -0.00015, 2e-5);   // docs/maths.md LP-4 a: (-1.890, -0.00015)
  EXPECT_NEAR(y2, -0.000013, 5e-6);  //             (-0.990, -0.000013)
  const Eigen::Vector3d mid(0.5 * (-1.890 - 0.990), 0.5 * (y1 + y2), 0.0);
  const double f_mid = m.Value(mid);
  EXPECT_GT(f_mid, 4.0e-3);  // docs/maths.md: +4.7e-3, outside: the solid {f <= 0} is not convex
  EXPECT_LT(f_mid, 5.5e-3);
}

TEST(LiPhillipsSmoothMax, SmoothAbsIsNeitherConvexNorOneLipschitz) {
  // Order 3, eps = delta = 1: S_abs'' dips to -0.2115 just outside |t| = delta, |S_abs'| reaches
  // 1.0387 (docs/maths.md LP-4 a). Central differences on a dense grid.
  const double h = 1e-4;
  double min_second = 0.0, max_slope = 0.0;
  for (int i = 0; i <= 40000; ++i) {
    const double t = -2.5 + 5.0 * i / 40000.0;
    const double sp = SmoothAbs(t + h, 1.0, 1.0, 3), s0 = SmoothAbs(t, 1.0, 1.0, 3),
                 sm = SmoothAbs(t - h, 1.0, 1.0, 3);
    min_second = std::min(min_second, (sp - 2 * s0 + sm) / (h * h));
    max_slope = std::max(max_slope, std::abs(sp - sm) / (2 * h));
  }
  EXPECT_NEAR(min_second, -0.2115, 2e-3);
  EXPECT_NEAR(max_slope, 1.0387, 1e-3);
}

TEST(LiPhillipsSmoothMax, IsNotMonotoneInItsArguments) {
  // dS_max/dy = (1 - S_abs'(x - y)) / 2 is about -0.019 somewhere (order 3, eps = delta).
  const double h = 1e-5;
  double min_partial = 1.0;
  for (int i = 0; i <= 20000; ++i) {
    const double x = -2.5 + 5.0 * i / 20000.0;
    const double d = (SmoothMax(x, h, 1.0, 1.0, 3) - SmoothMax(x, -h, 1.0, 1.0, 3)) / (2 * h);
    min_partial = std::min(min_partial, d);
  }
  EXPECT_NEAR(min_partial, -0.019, 1.5e-3);
}

}  // namespace
}  // namespace implicitfit
