// The convexity-preserving smooth abs / max (model/blends/convex_smooth_ops.h, docs/maths.md LP-4 b) and the
// "smoothing": "convex" blend option. Expected values: closed forms (S^c(0) = 13w/48 for n = 3,
// w/2 for n = 1), Simpson quadrature of H_n (model/blends/unit_step.h, not the integrated pieces),
// finite differences, |t| outside the band.
#include <ceres/jet.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "model/blends/convex_smooth_ops.h"
#include "model/model.h"
#include "model/file/model_json.h"

namespace implicitfit {
namespace {

TEST(ConvexSmoothAbs, ValueAtZeroMatchesTheClosedForms) {
  for (double w : {0.3, 1.0, 2.5}) {
    EXPECT_NEAR(ConvexSmoothAbs(0.0, w, 1), w / 2, 1e-15 * w);
    EXPECT_NEAR(ConvexSmoothAbs(0.0, w, 3), 13.0 * w / 48.0, 1e-15 * w);
  }
}

TEST(ConvexSmoothAbs, AgreesWithSimpsonQuadratureOfTheUnitStep) {
  // S^c(t) = -t + 2 w integral_{-1}^{t/w} H_n(u) du; composite Simpson on each of H_n's pieces
  // (exact for the degree-n pieces up to rounding when the nodes fall on the knots).
  for (int n = 1; n <= 10; ++n) {
    const UnitStep& h = UnitStep::OfOrder(n);
    const double w = 0.8;
    for (int i = 0; i <= 40; ++i) {
      const double t = -w + 2 * w * i / 40.0;
      const double u_end = t / w;
      const int m = 2000;  // even
      double sum = 0.0;
      const double du = (u_end + 1.0) / m;
      for (int q = 0; q <= m; ++q) {
        const double c = (q == 0 || q == m) ? 1 : (q % 2 ? 4 : 2);
        sum += c * h(-1.0 + q * du);
      }
      const double integral = sum * du / 3.0;
      EXPECT_NEAR(ConvexSmoothAbs(t, w, n), -t + 2 * w * integral, 1e-8) << "n " << n << " t " << t;
    }
  }
}

TEST(ConvexSmoothAbs, IsConvexOneLipschitzAndExactOutsideTheBand) {
  for (int n = 1; n <= UnitStep::kMaxOrder; ++n) {
    const double w = 0.7, h = 1e-2 * w;
    double min_second = 1.0, max_slope = 0.0;
    for (int i = 0; i <= 20000; ++i) {
      const double t = -1.5 * w + 3.0 * w * i / 20000.0;
      const double sp = ConvexSmoothAbs(t + h, w, n), s0 = ConvexSmoothAbs(t, w, n),
                   sm = ConvexSmoothAbs(t - h, w, n);
      min_second = std::min(min_second, (sp - 2 * s0 + sm) / (h * h));
      // Exact slope by a Jet, against S' = 2 mu_w - 1 from the unit step.
      using J = ceres::Jet<double, 1>;
      const J s = ConvexSmoothAbs(J(t, 0), J(w), n);
      EXPECT_NEAR(s.v[0], 2.0 * UnitStep::OfOrder(n)(t / w) - 1.0, 1e-12) << n << " " << t;
      max_slope = std::max(max_slope, std::abs(s.v[0]));
      if (std::abs(t) >= w) {
        EXPECT_EQ(s0, std::abs(t));
      } else {
        EXPECT_GE(s0, std::abs(t) - 1e-15);
      }
    }
    EXPECT_GE(min_second, -1e-10) << "order " << n;
    EXPECT_LE(max_slope, 1.0 + 1e-12) << "order " << n;
    // Continuity at the band's ends (the integrated pieces sum to area 1).
    EXPECT_NEAR(ConvexSmoothAbs(w * (1 - 1e-12), w, n), w, 1e-11) << n;
    EXPECT_NEAR(ConvexSmoothAbs(-w * (1 - 1e-12), w, n), w, 1e-11) << n;
  }
}

TEST(ConvexSmoothMax, JetsAgreeWithCentralDifferences) {
  using J = ceres::Jet<double, 3>;
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int n : {1, 2, 3, 5}) {
    for (int trial = 0; trial < 200; ++trial) {
      const double x = u(rng), y = u(rng), w = 0.3 + 0.5 * (u(rng) + 1);
      const J m = ConvexSmoothMax(J(x, 0), J(y, 1), J(w, 2), n);
      const double e = 1e-6;
      const double dx =
          (ConvexSmoothMax(x + e, y, w, n) - ConvexSmoothMax(x - e, y, w, n)) / (2 * e);
      const double dy =
          (ConvexSmoothMax(x, y + e, w, n) - ConvexSmoothMax(x, y - e, w, n)) / (2 * e);
      const double dw =
          (ConvexSmoothMax(x, y, w + e, n) - ConvexSmoothMax(x, y, w - e, n)) / (2 * e);
      EXPECT_NEAR(m.a, ConvexSmoothMax(x, y, w, n), 1e-15);
      EXPECT_NEAR(m.v[0], dx, 1e-7);
      EXPECT_NEAR(m.v[1], dy, 1e-7);
      EXPECT_NEAR(m.v[2], dw, 1e-7);
      // Monotone in both arguments (the Li-Phillips max is not).
      EXPECT_GE(m.v[0], -1e-15);
      EXPECT_GE(m.v[1], -1e-15);
    }
  }
}

Model ConvexWedge(NodeType type) {
  Model m;
  const int a = m.AddPrimitive(NodeType::kPlane, {1, 0, 0, 0});
  const int b = m.AddPrimitive(NodeType::kSphere, {0.2, 0, 0, 0.5});
  const int op = m.AddOperator(type, {a, b}, 0.25, 0.25, 3);
  m.mutable_nodes()[op].smoothing = BlendSmoothing::kConvex;
  return m;
}

TEST(ConvexSmoothing, TreeNodesEvaluateTheConvexOperators) {
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (NodeType type : {NodeType::kUnion, NodeType::kIntersection, NodeType::kDifference}) {
    const Model m = ConvexWedge(type);
    for (int i = 0; i < 100; ++i) {
      const Eigen::Vector3d x(u(rng), u(rng), u(rng));
      const double a = x.x(), b = (x - Eigen::Vector3d(0.2, 0, 0)).norm() - 0.5;
      const double expected = type == NodeType::kUnion          ? -ConvexSmoothMax(-a, -b, 0.25, 3)
                              : type == NodeType::kIntersection ? ConvexSmoothMax(a, b, 0.25, 3)
                                                                : ConvexSmoothMax(a, -b, 0.25, 3);
      EXPECT_DOUBLE_EQ(m.Value(x), expected);
    }
  }
}

TEST(ConvexSmoothing, JsonRoundTripWritesNoEpsilonAndOldFilesStayUnchanged) {
  const Model m = ConvexWedge(NodeType::kIntersection);
  const nlohmann::json j = ModelToJson(m);
  EXPECT_EQ(j["root"]["smoothing"], "convex");
  EXPECT_FALSE(j["root"].contains("epsilon"));
  const Model back = ModelFromJson(j);
  EXPECT_EQ(back.nodes()[back.root()].smoothing, BlendSmoothing::kConvex);
  EXPECT_EQ(ModelToJson(back), j);
  for (double x : {-0.4, -0.1, 0.0, 0.13, 0.5})
    EXPECT_EQ(back.Value(Eigen::Vector3d(x, 0.1, 0.0)), m.Value(Eigen::Vector3d(x, 0.1, 0.0)));

  // A file without "smoothing" reads as Li-Phillips and is written back without the field.
  const nlohmann::json old = nlohmann::json::parse(R"({"format": "implicitfit-model", "version": 1,
      "root": {"type": "union", "delta": 0.3, "epsilon": 0.2, "order": 2, "children": [
        {"type": "plane", "normal": [0, 0, 1], "offset": 0},
        {"type": "plane", "normal": [1, 0, 0], "offset": 0}]}})");
  const Model old_model = ModelFromJson(old);
  EXPECT_EQ(old_model.nodes()[old_model.root()].smoothing, BlendSmoothing::kLiPhillips);
  EXPECT_EQ(ModelToJson(old_model), old);
  nlohmann::json explicit_lp = old;
  explicit_lp["root"]["smoothing"] = "li-phillips";
  EXPECT_EQ(ModelToJson(ModelFromJson(explicit_lp)), old);
}

TEST(ConvexSmoothing, RefusesEpsilonAndUnknownValuesNamingThePath) {
  nlohmann::json j = ModelToJson(ConvexWedge(NodeType::kUnion));
  j["root"]["epsilon"] = 0.1;
  try {
    ModelFromJson(j);
    FAIL() << "epsilon with convex smoothing accepted";
  } catch (const ModelFormatError& e) {
    EXPECT_NE(std::string(e.what()).find("root.epsilon"), std::string::npos) << e.what();
  }
  j["root"].erase("epsilon");
  j["root"]["smoothing"] = "round";
  try {
    ModelFromJson(j);
    FAIL() << "unknown smoothing accepted";
  } catch (const ModelFormatError& e) {
    EXPECT_NE(std::string(e.what()).find("root.smoothing"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace implicitfit
