// docs/maths.md TB-3 check 5 and the bspline_surface node: the NURBS quarter circle lies on the
// circle, the NURBS quarter cylinder's signed distance is rho - 1, rational derivatives match
// finite differences, and the node's foot point and gradients agree with brute force.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "model/dual3.h"
#include "model/file/model_json.h"
#include "model/model.h"
#include "model/splines/bspline_evaluation.h"
#include "model/splines/closest_point.h"

namespace implicitfit {
namespace {

const double kW = std::sqrt(0.5);

SplineStructure QuarterCircle() {
  SplineStructure s;
  s.degree[0] = 2;
  s.count[0] = 3;
  s.knots[0] = {0, 0, 0, 1, 1, 1};
  s.weights = {1.0, kW, 1.0};
  return s;
}

TEST(Nurbs, QuarterCircleLiesOnTheCircle) {
  const SplineStructure s = QuarterCircle();
  const double P[9] = {1, 0, 0, 1, 1, 0, 0, 1, 0};
  double worst = 0.0;
  for (int i = 0; i <= 1000; ++i) {
    double out[kMaxSplineDerivative + 1][3];
    CurveDerivatives(s, P, i / 1000.0, 0, out);
    worst = std::max(worst, std::abs(std::hypot(out[0][0], out[0][1]) - 1.0));
    EXPECT_GE(out[0][0], -1e-16);
    EXPECT_GE(out[0][1], -1e-16);
  }
  EXPECT_LE(worst, 1e-15);
}

// The quarter cylinder x^2 + y^2 = 1, x, y >= 0, 0 <= z <= 1: the circle along u, a line in z
// along v; S_u x S_v points away from the axis.
Model QuarterCylinder() {
  SplineStructure s;
  s.degree[0] = 2;
  s.degree[1] = 1;
  s.count[0] = 3;
  s.count[1] = 2;
  s.knots[0] = {0, 0, 0, 1, 1, 1};
  s.knots[1] = {0, 0, 1, 1};
  s.weights = {1, 1, kW, kW, 1, 1};
  const std::vector<double> points = {1, 0, 0, 1, 0, 1, 1, 1, 0, 1, 1, 1, 0, 1, 0, 0, 1, 1};
  Model m;
  m.AddBSplineSurface(s, points);
  return m;
}

TEST(Nurbs, QuarterCylinderSignedDistanceIsRhoMinusOne) {
  const Model m = QuarterCylinder();
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  double worst = 0.0;
  for (int i = 0; i < 2000; ++i) {
    const double rho = 0.3 + 1.7 * u01(rng), phi = 0.5 * M_PI * u01(rng), z = u01(rng);
    const Eigen::Vector3d x(rho * std::cos(phi), rho * std::sin(phi), z);
    worst = std::max(worst, std::abs(m.Value(x) - (rho - 1.0)));
  }
  EXPECT_LE(worst, 1e-9);
}

// Rational surface derivatives (A4.4) against central differences of the points.
TEST(Nurbs, RationalSurfaceDerivativesMatchFiniteDifferences) {
  const Model m = QuarterCylinder();
  const SplineStructure& s = m.nodes()[0].spline;
  SplineStructure bent = s;
  bent.weights = {1, 2, 0.5, 0.7, 1.5, 1};  // arbitrary positive weights: a general NURBS
  std::vector<double> P = m.parameters();
  P[4] += 0.3;
  P[9] -= 0.2;
  const double* p = P.data();
  const double h = 1e-5;
  for (double u : {0.2, 0.55, 0.9})
    for (double v : {0.15, 0.6}) {
      double d[3][3][3], a[3][3][3], b[3][3][3];
      SurfaceDerivatives(bent, p, u, v, 2, d);
      SurfaceDerivatives(bent, p, u + h, v, 1, a);
      SurfaceDerivatives(bent, p, u - h, v, 1, b);
      for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(d[1][0][c], (a[0][0][c] - b[0][0][c]) / (2 * h), 1e-8);
        EXPECT_NEAR(d[2][0][c], (a[1][0][c] - b[1][0][c]) / (2 * h), 1e-6);
        EXPECT_NEAR(d[1][1][c], (a[0][1][c] - b[0][1][c]) / (2 * h), 1e-6);
      }
      SurfaceDerivatives(bent, p, u, v + h, 1, a);
      SurfaceDerivatives(bent, p, u, v - h, 1, b);
      for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(d[0][1][c], (a[0][0][c] - b[0][0][c]) / (2 * h), 1e-8);
        EXPECT_NEAR(d[0][2][c], (a[0][1][c] - b[0][1][c]) / (2 * h), 1e-6);
      }
    }
}

// A wavy bicubic patch: the foot by Newton is no farther than the best of a dense brute-force
// sampling, and the node's gradient (Dual3) is the unit vector from the foot, with the sign of
// S_u x S_v.
Model WavyPatch() {
  SplineStructure s;
  s.degree[0] = s.degree[1] = 3;
  s.count[0] = 6;
  s.count[1] = 5;
  s.knots[0] = ClampedUniformKnots(3, 6, 0, 1);
  s.knots[1] = ClampedUniformKnots(3, 5, 0, 1);
  std::vector<double> points;
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 5; ++j)
      points.insert(points.end(), {i * 0.4, j * 0.5, 0.3 * std::sin(1.7 * i) * std::cos(1.1 * j)});
  Model m;
  m.AddBSplineSurface(s, points);
  return m;
}

TEST(BSplineSurfaceNode, FootIsTheClosestPointOfADenseSampling) {
  const Model m = WavyPatch();
  const SplineStructure& s = m.nodes()[0].spline;
  const double* p = m.parameters().data();
  std::vector<Eigen::Vector3d> dense;
  for (int i = 0; i <= 300; ++i)
    for (int j = 0; j <= 300; ++j) {
      double d[3][3][3];
      SurfaceDerivatives(s, p, i / 300.0, j / 300.0, 0, d);
      dense.emplace_back(d[0][0][0], d[0][0][1], d[0][0][2]);
    }
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> box(-0.5, 2.5);
  for (int trial = 0; trial < 60; ++trial) {
    const Eigen::Vector3d x(box(rng), box(rng), 0.6 * box(rng) - 0.3);
    double brute = INFINITY;
    for (const Eigen::Vector3d& y : dense) brute = std::min(brute, (x - y).norm());
    const SurfaceFoot foot = ClosestSurfacePoint(s, p, x.data());
    const double newton = std::sqrt(foot.distance2);
    EXPECT_LE(newton, brute + 1e-12) << "x " << x.transpose();
    EXPECT_GE(newton, brute - 5e-3);  // the sampling's resolution
    EXPECT_NEAR(std::abs(m.Value(x)), newton, 1e-12);
  }
}

TEST(BSplineSurfaceNode, GradientIsTheUnitDirectionFromTheFoot) {
  const Model m = WavyPatch();
  const double h = 1e-6;
  for (const Eigen::Vector3d& x : {Eigen::Vector3d(0.9, 1.1, 0.4), Eigen::Vector3d(1.3, 0.7, -0.5),
                                  Eigen::Vector3d(2.4, 1.0, 0.2), Eigen::Vector3d(-0.4, -0.3, 0.1)}) {
    double f;
    const Eigen::Vector3d g = m.Gradient(x, &f);
    EXPECT_NEAR(g.norm(), 1.0, 1e-9);
    for (int k = 0; k < 3; ++k) {
      Eigen::Vector3d e = Eigen::Vector3d::Zero();
      e[k] = h;
      EXPECT_NEAR(g[k], (m.Value(x + e) - m.Value(x - e)) / (2 * h), 1e-6) << x.transpose();
    }
  }
  // Above the patch (z large) is the side of S_u x S_v (x along u, y along v: +z).
  EXPECT_GT(m.Value(Eigen::Vector3d(1.0, 1.0, 2.0)), 0.0);
  EXPECT_LT(m.Value(Eigen::Vector3d(1.0, 1.0, -2.0)), 0.0);
}

// Derivatives in the control points (Jets through Dual3 on a parameter): a central difference.
TEST(BSplineSurfaceNode, DerivativeInAControlPointMatchesFiniteDifferences) {
  Model m = WavyPatch();
  const Eigen::Vector3d x(0.9, 1.2, 0.35);
  for (int k : {2, 38, 44, 59}) {
    std::vector<Dual3> p(m.parameters().begin(), m.parameters().end());
    p[k] = Dual3(m.parameters()[k], Eigen::Vector3d::UnitX());
    const Dual3 xd[3] = {Dual3(x[0]), Dual3(x[1]), Dual3(x[2])};
    const double analytic = m.Evaluate(p.data(), xd).v[0];
    const double h = 1e-6, x0 = m.parameters()[k];
    m.mutable_parameters()[k] = x0 + h;
    const double fp = m.Value(x);
    m.mutable_parameters()[k] = x0 - h;
    const double fm = m.Value(x);
    m.mutable_parameters()[k] = x0;
    EXPECT_NEAR(analytic, (fp - fm) / (2 * h), 1e-7) << "parameter " << k;
  }
}

TEST(BSplineSurfaceNode, JsonRoundTripAndRefusals) {
  const Model m = QuarterCylinder();
  const nlohmann::json j = ModelToJson(m);
  const Model back = ModelFromJson(j);
  EXPECT_EQ(back.parameters(), m.parameters());
  EXPECT_EQ(back.nodes()[0].spline.weights, m.nodes()[0].spline.weights);
  EXPECT_EQ(ModelToJson(back), j);
  auto refused = [&](const std::function<void(nlohmann::json&)>& edit, const std::string& part) {
    nlohmann::json bad = j;
    edit(bad["root"]);
    try {
      ModelFromJson(bad);
      ADD_FAILURE() << "accepted: " << part;
    } catch (const ModelFormatError& e) {
      EXPECT_NE(std::string(e.what()).find(part), std::string::npos) << e.what();
    }
  };
  refused([](nlohmann::json& r) { r["degree"] = {9, 1}; }, "root.degree[0]");
  refused([](nlohmann::json& r) { r["degree"] = {3, 1}; }, "root.control_points");
  refused([](nlohmann::json& r) { r["weights"][1][0] = -1.0; }, "root.weights[1][0]");
  refused([](nlohmann::json& r) { r["knots_u"] = {0, 0, 0, 1, 1}; }, "root.knots_u");
  refused([](nlohmann::json& r) { r["knots_v"] = {0, 0.5, 0.2, 1}; }, "root.knots_v");
  refused([](nlohmann::json& r) { r["control_points"][1].erase(1); }, "root.control_points[1]");
  refused([](nlohmann::json& r) { r["colour"] = 1; }, "root.colour");
  nlohmann::json big = j;  // more rows than the limit: refused before anything is allocated
  big["root"]["control_points"] = nlohmann::json::array();
  for (int i = 0; i <= SplineLimits::kMaxControlPointsPerAxis; ++i)
    big["root"]["control_points"].push_back({{0, 0, 0}, {1, 0, 0}});
  EXPECT_THROW(ModelFromJson(big), ModelFormatError);
  // Knots omitted: clamped uniform on [0, 1].
  nlohmann::json plain = j;
  plain["root"].erase("knots_u");
  plain["root"].erase("knots_v");
  EXPECT_EQ(ModelFromJson(plain).nodes()[0].spline.knots[1], (std::vector<double>{0, 0, 1, 1}));
}

}  // namespace
}  // namespace implicitfit
