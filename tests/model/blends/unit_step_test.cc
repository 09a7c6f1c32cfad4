// H_n against the literal recursion of the paper (oracle) and against its defining properties.
#include "model/blends/unit_step.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>

#include "oracle/li_phillips_oracle.h"

namespace implicitfit {
namespace {

TEST(UnitStep, MatchesTheRecursionOfEquations2And3ForEveryOrder) {
  for (int n = 0; n <= 12; ++n) {  // the oracle costs 2^n per call
    const UnitStep& h = UnitStep::OfOrder(n);
    for (int i = 0; i <= 400; ++i) {
      const double t = -1.2 + 2.4 * i / 400.0;
      EXPECT_NEAR(h(t), oracle::H(n, t), 1e-12) << "n=" << n << " t=" << t;
    }
  }
}

TEST(UnitStep, IsZeroBelowMinusOneAndOneAboveOne) {
  for (int n = 0; n <= UnitStep::kMaxOrder; ++n) {
    const UnitStep& h = UnitStep::OfOrder(n);
    for (double t : {-50.0, -1.0001, -1.0}) EXPECT_EQ(h(t), 0.0) << n;
    for (double t : {1.0, 1.0001, 50.0}) EXPECT_EQ(h(t), 1.0) << n;
  }
}

TEST(UnitStep, IsOneHalfAtZeroAndAntisymmetric) {
  for (int n = 0; n <= UnitStep::kMaxOrder; ++n) {
    const UnitStep& h = UnitStep::OfOrder(n);
    EXPECT_NEAR(h(0.0), 0.5, 1e-13) << n;
    for (int i = 1; i < 100; ++i) {
      const double t = i / 100.0;
      EXPECT_NEAR(h(-t), 1.0 - h(t), 1e-12) << "n=" << n << " t=" << t;
    }
  }
}

TEST(UnitStep, IsMonotoneAndWithinZeroOne) {
  for (int n = 1; n <= UnitStep::kMaxOrder; ++n) {
    const UnitStep& h = UnitStep::OfOrder(n);
    double previous = 0.0;
    for (int i = 0; i <= 2000; ++i) {
      const double v = h(-1.0 + 2.0 * i / 2000.0);
      EXPECT_GE(v, previous - 1e-14) << n;
      EXPECT_GE(v, -1e-14);
      EXPECT_LE(v, 1.0 + 1e-14);
      previous = v;
    }
  }
}

// Derivatives of the polynomial piece on one side of a knot, from values of H only: H is a
// polynomial of degree n on each piece, so the interpolant through n + 1 samples taken inside
// the piece is that polynomial; its Taylor coefficients at the knot give the one-sided
// derivatives (k! c_k). Solved in long double in the local coordinate (x - knot) / width.
std::vector<long double> OneSidedDerivatives(const UnitStep& h, double knot, double side) {
  const int n = h.order();
  const double width = 2.0 / n;
  Eigen::Matrix<long double, Eigen::Dynamic, Eigen::Dynamic> V(n + 1, n + 1);
  Eigen::Matrix<long double, Eigen::Dynamic, 1> y(n + 1);
  for (int i = 0; i <= n; ++i) {
    const long double s = side * (i + 1.0L) / (n + 2.0L);  // strictly inside the piece
    for (int k = 0; k <= n; ++k) V(i, k) = std::pow(s, k);
    y[i] = h(knot + static_cast<double>(s) * width);
  }
  const Eigen::Matrix<long double, Eigen::Dynamic, 1> c = V.fullPivLu().solve(y);
  std::vector<long double> derivatives(n + 1);
  long double factorial = 1.0L;
  for (int k = 0; k <= n; ++k) {
    if (k > 0) factorial *= k;
    derivatives[k] = factorial * c[k] / std::pow(static_cast<long double>(width), k);
  }
  return derivatives;
}

TEST(UnitStep, IsCnMinusOneAtTheKnotsAndNotCn) {
  // Knots of H_n: t_j = 2 j / n - 1, j = 0..n. Derivatives of order < n agree from both sides;
  // outside [-1, 1] H is constant (all derivatives 0). The n-th derivative jumps at every knot.
  for (int n = 2; n <= 8; ++n) {
    const UnitStep& h = UnitStep::OfOrder(n);
    for (int j = 0; j <= n; ++j) {
      const double knot = 2.0 * j / n - 1.0;
      std::vector<long double> left(n + 1, 0.0L), right(n + 1, 0.0L);
      if (j > 0)
        left = OneSidedDerivatives(h, knot, -1.0);
      else
        left[0] = 0.0L;
      if (j < n)
        right = OneSidedDerivatives(h, knot, +1.0);
      else
        right[0] = 1.0L;
      const double scale = std::pow(n / 2.0, n);  // d^k/dt^k scales like (n/2)^k
      for (int k = 0; k <= n - 1; ++k)
        EXPECT_NEAR(static_cast<double>(left[k]), static_cast<double>(right[k]), 1e-7 * scale)
            << "n=" << n << " knot " << j << " derivative " << k;
      EXPECT_GT(std::abs(static_cast<double>(left[n] - right[n])), 1e-3)
          << "n=" << n << " knot " << j;
    }
  }
}

TEST(UnitStep, OrderOneIsTheLinearRamp) {
  const UnitStep& h = UnitStep::OfOrder(1);
  for (double t : {-0.9, -0.3, 0.2, 0.75}) EXPECT_NEAR(h(t), (t + 1.0) / 2.0, 1e-15);
}

TEST(UnitStep, RisingRangeScalesTheSupport) {
  const UnitStep& h = UnitStep::OfOrder(3);
  const double eps = 0.25;
  EXPECT_EQ(h.WithRisingRange(-0.26, eps), 0.0);
  EXPECT_EQ(h.WithRisingRange(0.26, eps), 1.0);
  EXPECT_NEAR(h.WithRisingRange(0.1, eps), oracle::H(3, 0.4), 1e-14);
}

TEST(UnitStep, RefusesOrdersOutsideTheTable) {
  EXPECT_THROW(UnitStep::OfOrder(-1), std::invalid_argument);
  EXPECT_THROW(UnitStep::OfOrder(UnitStep::kMaxOrder + 1), std::invalid_argument);
}

}  // namespace
}  // namespace implicitfit
