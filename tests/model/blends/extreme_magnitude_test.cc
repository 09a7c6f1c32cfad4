// Every smooth operator (Li & Phillips' and the convexity-preserving one: abs, union,
// intersection, difference) at extreme magnitudes, 1e-15 .. 1e17 for the arguments and the blend
// widths, against long double references (tests/oracle/long_double_blends.h: the papers' formulas
// in a translated frame, H_n by its recursion, S^c by Gauss-Legendre quadrature). The result must
// be within a few double roundings of the reference relative to max(|result|, delta + eps): no
// cancellation of the smaller argument. And the cases that used to cancel: the order-3 smooth
// intersection of the planes x = 1e17 and y = 1 is -1 at the origin (it was 0), and an
// ellipsoid's or quadric's centre is finite (it was -1e150, which made any smooth intersection
// containing it exactly 0 there).
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "model/blends/convex_smooth_ops.h"
#include "model/blends/smooth_ops.h"
#include "model/model.h"
#include "oracle/long_double_blends.h"

namespace implicitfit {
namespace {

using oracle::LD;

double LogUniform(std::mt19937& rng, double lo, double hi) {
  std::uniform_real_distribution<double> u(std::log(lo), std::log(hi));
  return std::exp(u(rng));
}

// x, y with random signs over 1e-15..1e17; one case in four puts y within the blend band of x.
void Draw(std::mt19937& rng, double band, double* x, double* y) {
  std::uniform_int_distribution<int> coin(0, 1), four(0, 3);
  *x = LogUniform(rng, 1e-15, 1e17) * (coin(rng) ? 1 : -1);
  if (four(rng) == 0) {
    std::uniform_real_distribution<double> u(-1.5, 1.5);
    *y = *x + u(rng) * band;
  } else {
    *y = LogUniform(rng, 1e-15, 1e17) * (coin(rng) ? 1 : -1);
  }
}

double Tolerance(LD reference, double band) {
  return 8 * 2.220446049250313e-16 * std::max<double>(std::fabs(static_cast<double>(reference)), band);
}

TEST(ExtremeMagnitudes, LiPhillipsOperatorsAgreeWithTheLongDoubleReference) {
  std::mt19937 rng(28);
  for (int trial = 0; trial < 20000; ++trial) {
    const int n = trial % 8;
    const double delta = LogUniform(rng, 1e-15, 1e17);
    const double eps = delta * LogUniform(rng, 1e-3, 1.0);
    double a, b;
    Draw(rng, delta + eps, &a, &b);
    const LD s = oracle::SMaxL(a, b, delta, eps, n);
    const LD u = -oracle::SMaxL(-static_cast<LD>(a), -static_cast<LD>(b), delta, eps, n);
    const LD d = oracle::SMaxL(a, -static_cast<LD>(b), delta, eps, n);
    const double band = delta + eps;
    ASSERT_NEAR(SmoothIntersection(a, b, delta, eps, n), static_cast<double>(s), Tolerance(s, band))
        << "a " << a << " b " << b << " delta " << delta << " eps " << eps << " n " << n;
    ASSERT_NEAR(SmoothUnion(a, b, delta, eps, n), static_cast<double>(u), Tolerance(u, band))
        << "a " << a << " b " << b << " delta " << delta << " eps " << eps << " n " << n;
    ASSERT_NEAR(SmoothDifference(a, b, delta, eps, n), static_cast<double>(d), Tolerance(d, band))
        << "a " << a << " b " << b << " delta " << delta << " eps " << eps << " n " << n;
    const LD t = oracle::SAbsL(a - static_cast<LD>(b), delta, eps, n);
    ASSERT_NEAR(SmoothAbs(a - b, delta, eps, n), static_cast<double>(t), Tolerance(t, band))
        << "t " << a - b << " delta " << delta << " eps " << eps << " n " << n;
  }
}

TEST(ExtremeMagnitudes, ConvexOperatorsAgreeWithTheLongDoubleReference) {
  std::mt19937 rng(29);
  for (int trial = 0; trial < 20000; ++trial) {
    const int n = trial % 8;
    const double w = LogUniform(rng, 1e-15, 1e17);
    double a, b;
    Draw(rng, w, &a, &b);
    const LD s = oracle::ConvexSMaxL(a, b, w, n);
    const LD u = -oracle::ConvexSMaxL(-static_cast<LD>(a), -static_cast<LD>(b), w, n);
    const LD d = oracle::ConvexSMaxL(a, -static_cast<LD>(b), w, n);
    ASSERT_NEAR(ConvexSmoothIntersection(a, b, w, n), static_cast<double>(s), Tolerance(s, w))
        << "a " << a << " b " << b << " w " << w << " n " << n;
    ASSERT_NEAR(ConvexSmoothUnion(a, b, w, n), static_cast<double>(u), Tolerance(u, w))
        << "a " << a << " b " << b << " w " << w << " n " << n;
    ASSERT_NEAR(ConvexSmoothDifference(a, b, w, n), static_cast<double>(d), Tolerance(d, w))
        << "a " << a << " b " << b << " w " << w << " n " << n;
    const LD t = oracle::ConvexSAbsL(a - static_cast<LD>(b), w, n);
    ASSERT_NEAR(ConvexSmoothAbs(a - b, w, n), static_cast<double>(t), Tolerance(t, w))
        << "t " << a - b << " w " << w << " n " << n;
  }
}

TEST(ExtremeMagnitudes, TheIntersectionOfTwoFarPlanesDoesNotCancel) {
  // Planes x = 1e17 and y = 1 (f = x - 1e17, f = y - 1); at the origin f = max(-1e17, -1) = -1,
  // exactly: the two values are far outside the blend band.
  for (BlendSmoothing smoothing : {BlendSmoothing::kLiPhillips, BlendSmoothing::kConvex}) {
    Model m;
    const int a = m.AddPrimitive(NodeType::kPlane, {1, 0, 0, 1e17});
    const int b = m.AddPrimitive(NodeType::kPlane, {0, 1, 0, 1});
    const int op = m.AddOperator(NodeType::kIntersection, {a, b}, 0.5, 0.25, 3);
    m.mutable_nodes()[op].smoothing = smoothing;
    EXPECT_EQ(m.Value(Eigen::Vector3d::Zero()), -1.0);
    const Eigen::Vector3d g = m.Gradient(Eigen::Vector3d::Zero());
    EXPECT_EQ(g, Eigen::Vector3d(0, 1, 0));
  }
}

TEST(ExtremeMagnitudes, EllipsoidAndQuadricCentresAreFinite) {
  // Ellipsoid with radii 2, 1, 0.5: the first-order distance tends to -r_i along axis i, so at
  // the centre any value in [-2, -0.5] is a limit; it must be finite and in that range.
  Model e;
  e.AddPrimitive(NodeType::kEllipsoid, {0.3, -0.2, 0.1, 2, 1, 0.5, 1, 0, 0, 0, 1, 0});
  const Eigen::Vector3d ce(0.3, -0.2, 0.1);
  const double fe = e.Value(ce);
  EXPECT_GE(fe, -2.0);
  EXPECT_LE(fe, -0.5);
  EXPECT_TRUE(e.Gradient(ce).allFinite());
  // The quadric |x|^2 - 4 (a sphere of radius 2): its value inside is the distance, -2 at the
  // centre; the ellipsoid (x/2)^2 + y^2 + (z/0.5)^2 - 1 lies in [-2, -0.5] there.
  Model q;
  q.AddPrimitive(NodeType::kQuadric, {1, 1, 1, 0, 0, 0, 0, 0, 0, -4});
  EXPECT_NEAR(q.Value(Eigen::Vector3d::Zero()), -2.0, 1e-15);
  EXPECT_NEAR(q.Value(Eigen::Vector3d(0.5, 0.2, -1.0)), std::sqrt(1.29) - 2.0, 1e-15);
  Model qe;
  qe.AddPrimitive(NodeType::kQuadric, {0.25, 1, 4, 0, 0, 0, 0, 0, 0, -1});
  const double fq = qe.Value(Eigen::Vector3d::Zero());
  EXPECT_GE(fq, -2.0);
  EXPECT_LE(fq, -0.5);
  // In a smooth intersection with a plane 1 away, the centre's value is the plane's -1, not 0.
  for (const Model* base : {&e, &q}) {
    Model m;
    const int b = m.AddPrimitive(base->nodes()[0].type, base->parameters());
    const Eigen::Vector3d c = base == &e ? ce : Eigen::Vector3d::Zero();
    const int p = m.AddPrimitive(NodeType::kPlane, {0, 0, 1, c.z() + 1});
    m.AddOperator(NodeType::kIntersection, {b, p}, 0.02, 0.01, 3);
    EXPECT_NEAR(m.Value(c), std::max(-1.0, base->Value(c)), 1e-15);
  }
}

}  // namespace
}  // namespace implicitfit
