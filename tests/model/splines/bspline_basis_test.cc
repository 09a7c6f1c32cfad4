// docs/maths.md TB-3 checks 1-4 and the basis derivatives: the triangular scheme against the
// Bernstein closed form, the partition of unity (right end included), the recursion with both
// conventions for 0/0, finite differences, and the Bezier end tangents.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "model/splines/bspline_basis.h"
#include "model/splines/bspline_evaluation.h"

namespace implicitfit {
namespace {

double Binomial(int n, int k) {
  double b = 1.0;
  for (int i = 1; i <= k; ++i) b = b * (n - k + i) / i;
  return b;
}

std::vector<double> AllBasis(int degree, int count, const std::vector<double>& knots, double t) {
  std::vector<double> all(static_cast<size_t>(count), 0.0);
  const int span = FindSpan(degree, count, knots.data(), t);
  double N[kMaxSplineDegree + 1];
  BasisFunctions(span, t, degree, knots.data(), N);
  for (int j = 0; j <= degree; ++j) all[span - degree + j] = N[j];
  return all;
}

// Check 1: order 4 (cubic) on [0,0,0,0,1,1,1,1] is the cubic Bernstein basis (Exercise 22.2-2).
TEST(BSplineBasis, CubicOnBezierKnotsIsBernstein) {
  const std::vector<double> knots = {0, 0, 0, 0, 1, 1, 1, 1};
  double worst = 0.0;
  for (int s = 0; s <= 200; ++s) {
    const double t = s / 200.0;
    const std::vector<double> N = AllBasis(3, 4, knots, t);
    for (int i = 0; i < 4; ++i) {
      const double bernstein = Binomial(3, i) * std::pow(t, i) * std::pow(1.0 - t, 3 - i);
      worst = std::max(worst, std::abs(N[i] - bernstein));
    }
  }
  EXPECT_LE(worst, 1e-15);
}

// Check 2: partition of unity on [u_p, u_n], both ends included, on uneven knots with
// multiplicities, for degrees 1..5.
TEST(BSplineBasis, PartitionOfUnityIncludingTheRightEnd) {
  for (int p = 1; p <= 5; ++p) {
    std::vector<double> knots(p + 1, -1.0);
    for (int m = 0; m < std::min(2, p); ++m) knots.push_back(-0.5);
    knots.push_back(0.1);
    for (int m = 0; m < std::min(3, p); ++m) knots.push_back(0.7);
    knots.push_back(1.3);
    for (int i = 0; i <= p; ++i) knots.push_back(2.0);
    const int n = static_cast<int>(knots.size()) - p - 1;
    ASSERT_EQ(KnotVectorProblem(knots, p, n), "");
    for (int s = 0; s <= 300; ++s) {
      const double t = -1.0 + 3.0 * s / 300.0;
      const std::vector<double> N = AllBasis(p, n, knots, t);
      double sum = 0.0;
      for (double v : N) {
        EXPECT_GE(v, -1e-15);
        sum += v;
      }
      EXPECT_NEAR(sum, 1.0, 1e-14) << "p " << p << " t " << t;
    }
    // The right end: the last basis function is 1 there, every other 0.
    const std::vector<double> end = AllBasis(p, n, knots, 2.0);
    EXPECT_DOUBLE_EQ(end.back(), 1.0);
    EXPECT_DOUBLE_EQ(end.front() + end.back(), 1.0);
  }
}

// Check 3: the recursion with 0/0 := 1 and with 0/0 := 0 gives the same basis, and the
// triangular scheme agrees with it, on knots with multiplicities.
TEST(BSplineBasis, RecursionConventionsAgreeWithTheTriangularScheme) {
  const std::vector<double> knots = {0, 0, 0, 0, 0.25, 0.5, 0.5, 0.5, 0.8, 1, 1, 1, 1};
  const int p = 3, n = static_cast<int>(knots.size()) - p - 1;
  ASSERT_EQ(KnotVectorProblem(knots, p, n), "");
  double worst = 0.0, largest = 0.0;
  for (int s = 0; s <= 100; ++s) {
    const double t = s / 100.0;
    const std::vector<double> N = AllBasis(p, n, knots, t);
    for (int i = 0; i < n; ++i) {
      const double one = CoxDeBoor(i, p, t, knots, n, 1.0);
      const double zero = CoxDeBoor(i, p, t, knots, n, 0.0);
      EXPECT_EQ(one, zero) << "i " << i << " t " << t;
      worst = std::max(worst, std::abs(one - N[i]));
      largest = std::max(largest, one);
    }
  }
  EXPECT_LE(worst, 1e-15);
  EXPECT_GT(largest, 0.5);
}

// Basis derivatives (A2.3) against central differences of the values, degrees 1..5.
TEST(BSplineBasis, DerivativesMatchFiniteDifferences) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  for (int p = 1; p <= 5; ++p) {
    const int n = p + 5;
    const std::vector<double> knots = ClampedUniformKnots(p, n, 0.0, 1.0);
    for (int trial = 0; trial < 50; ++trial) {
      const double t = 0.02 + 0.96 * u01(rng);
      const int span = FindSpan(p, n, knots.data(), t);
      double ders[3 * (kMaxSplineDegree + 1)];
      BasisDerivatives(span, t, p, std::min(2, p), knots.data(), ders);
      const double h = 1e-5;
      double plus[kMaxSplineDegree + 1], minus[kMaxSplineDegree + 1], mid[kMaxSplineDegree + 1];
      // The same span on both sides unless t is within h of a knot.
      if (FindSpan(p, n, knots.data(), t + h) != span ||
          FindSpan(p, n, knots.data(), t - h) != span)
        continue;
      BasisFunctions(span, t + h, p, knots.data(), plus);
      BasisFunctions(span, t - h, p, knots.data(), minus);
      BasisFunctions(span, t, p, knots.data(), mid);
      for (int j = 0; j <= p; ++j) {
        EXPECT_NEAR(ders[j], mid[j], 1e-15);
        EXPECT_NEAR(ders[(p + 1) + j], (plus[j] - minus[j]) / (2 * h), 1e-7 * n);
        if (p >= 2) {
          EXPECT_NEAR(ders[2 * (p + 1) + j], (plus[j] - 2 * mid[j] + minus[j]) / (h * h),
                      1e-3 * n * n);
        }
      }
    }
  }
}

// Check 4: a cubic Bezier curve's end tangents are 3 (P1 - P0) and 3 (P3 - P2) (Ex. 22.2-4).
TEST(BSplineBasis, BezierEndTangents) {
  SplineStructure s;
  s.degree[0] = 3;
  s.count[0] = 4;
  s.knots[0] = {0, 0, 0, 0, 1, 1, 1, 1};
  const double P[12] = {0, 0, 0, 1, 2, 0.5, 3, 2.5, -1, 4, 0, 2};
  for (double t : {0.0, 1.0}) {
    double out[kMaxSplineDerivative + 1][3];
    CurveDerivatives(s, P, t, 1, out);
    for (int c = 0; c < 3; ++c) {
      const double expected = t == 0.0 ? 3 * (P[3 + c] - P[c]) : 3 * (P[9 + c] - P[6 + c]);
      EXPECT_NEAR(out[1][c], expected, 1e-13);
      EXPECT_NEAR(out[0][c], t == 0.0 ? P[c] : P[9 + c], 1e-15);
    }
  }
}

TEST(BSplineBasis, KnotVectorProblemsAreNamed) {
  EXPECT_NE(KnotVectorProblem({0, 0, 1, 1}, 1, 3), "");            // wrong size
  EXPECT_NE(KnotVectorProblem({0, 0, 0.5, 0.2, 1, 1}, 1, 4), "");  // decreasing
  EXPECT_NE(KnotVectorProblem({0, 0, 0.5, 0.5, 1, 1}, 1, 4), "");  // interior repeated > p
  EXPECT_NE(KnotVectorProblem({0, 0, 0, 0, 0, 0}, 2, 3), "");      // empty range
  EXPECT_EQ(KnotVectorProblem(ClampedUniformKnots(3, 7, -2, 5), 3, 7), "");
  EXPECT_NE(KnotVectorProblem({0, 0, NAN, 1, 1}, 1, 3), "");
}

}  // namespace
}  // namespace implicitfit
