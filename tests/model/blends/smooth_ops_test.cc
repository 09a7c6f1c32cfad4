#include "model/blends/smooth_ops.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "oracle/li_phillips_oracle.h"

namespace implicitfit {
namespace {

TEST(SmoothAbs, IsAtLeastAbsAndExactOutsideTheBlendZone) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int trial = 0; trial < 200; ++trial) {
    const double delta = 0.05 + u(rng), eps = delta * (0.05 + 0.95 * u(rng));
    const int n = 1 + trial % 6;
    for (int i = 0; i <= 200; ++i) {
      const double t = (-3.0 + 6.0 * i / 200.0) * (delta + eps);
      const double s = SmoothAbs(t, delta, eps, n);
      EXPECT_GE(s, std::abs(t) - 1e-12);
      if (std::abs(t) >= delta + eps) {
        EXPECT_NEAR(s, std::abs(t), 1e-12 * (1 + std::abs(t)));
      }
    }
  }
}

TEST(SmoothAbs, EqualsTheParabolaInTheMiddle) {
  // For |t| <= delta - eps both steps are saturated (mu(t+delta) = 1, mu(t-delta) = 0).
  const double delta = 1.0, eps = 0.4;
  for (double t : {-0.6, -0.3, 0.0, 0.2, 0.6})
    EXPECT_NEAR(SmoothAbs(t, delta, eps, 3), t * t / (2 * delta) + delta / 2, 1e-14);
}

TEST(SmoothAbs, AgreesWithTheOracle) {
  for (int n = 0; n <= 8; ++n)
    for (int i = 0; i <= 100; ++i) {
      const double t = -2.0 + 4.0 * i / 100.0;
      EXPECT_NEAR(SmoothAbs(t, 0.7, 0.3, n), oracle::SAbs(t, 0.7, 0.3, n), 1e-12);
    }
}

TEST(SmoothMax, NeverFallsBelowMaxAndIsSymmetric) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-2.0, 2.0);
  for (int i = 0; i < 2000; ++i) {
    const double x = u(rng), y = u(rng);
    const double m = SmoothMax(x, y, 0.5, 0.25, 3);
    EXPECT_GE(m, std::max(x, y) - 1e-14);
    EXPECT_NEAR(m, SmoothMax(y, x, 0.5, 0.25, 3), 1e-14);
    if (std::abs(x - y) >= 0.75) {
      EXPECT_NEAR(m, std::max(x, y), 1e-14);
    }
  }
}

TEST(SmoothOperators, OrderZeroIsTheSharpMinMax) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-2.0, 2.0);
  for (int i = 0; i < 500; ++i) {
    const double a = u(rng), b = u(rng);
    EXPECT_EQ(SmoothUnion(a, b, 0.5, 0.5, 0), std::min(a, b));
    EXPECT_EQ(SmoothIntersection(a, b, 0.5, 0.5, 0), std::max(a, b));
    EXPECT_EQ(SmoothDifference(a, b, 0.5, 0.5, 0), std::max(a, -b));
  }
}

TEST(SmoothOperators, KeepTheInsideOutsideSemanticsAwayFromTheBlend) {
  // f < 0 inside. A point inside both solids (far from the blend) is inside the union and the
  // intersection; a point inside a only is inside the union and a - b, outside a intersect b.
  const double d = 0.2, e = 0.1;
  const int n = 2;
  EXPECT_LT(SmoothUnion(-1.0, -2.0, d, e, n), 0.0);
  EXPECT_LT(SmoothIntersection(-1.0, -2.0, d, e, n), 0.0);
  EXPECT_LT(SmoothUnion(-1.0, 1.0, d, e, n), 0.0);
  EXPECT_GT(SmoothIntersection(-1.0, 1.0, d, e, n), 0.0);
  EXPECT_LT(SmoothDifference(-1.0, 1.0, d, e, n), 0.0);
  EXPECT_GT(SmoothDifference(-1.0, -1.0 - 1.0, d, e, n), 0.0);
  // Union is the smooth min: never above min, equal to it when far apart.
  EXPECT_LE(SmoothUnion(0.1, 0.15, d, e, n), 0.1);
  EXPECT_DOUBLE_EQ(SmoothUnion(0.1, 0.5, d, e, n), 0.1);
}

}  // namespace
}  // namespace implicitfit
