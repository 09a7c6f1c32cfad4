// docs/maths.md TB-3 check 6: cubic B-spline interpolation through m + 1 points with end
// conditions is exact (the expected values are the data and, for a cubic polynomial curve,
// the polynomial itself).
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "model/splines/bspline_evaluation.h"
#include "model/splines/bspline_interpolation.h"

namespace implicitfit {
namespace {

Eigen::Vector3d Cubic(double t, int order) {
  const Eigen::Vector3d a(0.5, -1, 2), b(1, 0.3, -0.7), c(-0.4, 2, 0.1), d(0.2, -0.6, 0.9);
  if (order == 0) return a + t * (b + t * (c + t * d));
  if (order == 1) return b + t * (2 * c + 3 * t * d);
  return 2 * c + 6 * t * d;
}

Eigen::Vector3d At(const InterpolatedCurve& k, double t, int order) {
  double out[kMaxSplineDerivative + 1][3];
  CurveDerivatives(k.structure, k.control_points.data(), t, order, out);
  return Eigen::Vector3d(out[order][0], out[order][1], out[order][2]);
}

TEST(BSplineInterpolation, ReproducesACubicWithItsEndDerivatives) {
  const std::vector<double> t = {-1.0, -0.7, 0.1, 0.2, 0.9, 1.6};
  std::vector<Eigen::Vector3d> q;
  for (double s : t) q.push_back(Cubic(s, 0));
  InterpolationEnds ends;
  ends.kind = EndCondition::kDerivative;
  ends.start = Cubic(t.front(), 1);
  ends.end = Cubic(t.back(), 1);
  const InterpolatedCurve k = InterpolateCubicBSpline(q, ends, t);
  EXPECT_EQ(k.structure.count[0], 8);
  for (int i = 0; i <= 100; ++i) {
    const double s = -1.0 + 2.6 * i / 100.0;
    EXPECT_LE((At(k, s, 0) - Cubic(s, 0)).norm(), 1e-12) << s;
    EXPECT_LE((At(k, s, 1) - Cubic(s, 1)).norm(), 1e-11) << s;
  }
}

TEST(BSplineInterpolation, NaturalEndsPassThroughEveryPoint) {
  std::mt19937 rng(8);
  std::normal_distribution<double> g(0.0, 1.0);
  for (int m : {1, 2, 5, 40}) {
    std::vector<Eigen::Vector3d> q;
    for (int j = 0; j <= m; ++j) q.emplace_back(j + 0.3 * g(rng), g(rng), g(rng));
    const InterpolatedCurve k = InterpolateCubicBSpline(q);
    for (int j = 0; j <= m; ++j)
      EXPECT_LE((At(k, k.parameters[j], 0) - q[j]).norm(), 1e-11) << "m " << m << " j " << j;
    EXPECT_LE(At(k, k.parameters.front(), 2).norm(), 1e-9);
    EXPECT_LE(At(k, k.parameters.back(), 2).norm(), 1e-9);
    for (int j = 1; j <= m; ++j)  // chord length
      EXPECT_NEAR(k.parameters[j] - k.parameters[j - 1], (q[j] - q[j - 1]).norm(), 1e-12);
  }
}

TEST(BSplineInterpolation, RefusesBadInput) {
  EXPECT_THROW(InterpolateCubicBSpline({Eigen::Vector3d::Zero()}), std::invalid_argument);
  EXPECT_THROW(InterpolateCubicBSpline({Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()}),
               std::invalid_argument);
  EXPECT_THROW(InterpolateCubicBSpline({Eigen::Vector3d::Zero(), Eigen::Vector3d::Ones()}, {},
                                       {1.0, 0.5}),
               std::invalid_argument);
}

}  // namespace
}  // namespace implicitfit
