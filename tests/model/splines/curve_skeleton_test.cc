// Curve skeletons of skeleton_offset tubes (docs/maths.md TB-3, CO-1): a circle's tube is the
// torus (closed form), a helix's and a B-spline's distances agree with dense brute force, a
// Bezier curve is its clamped B-spline, the JSON forms round-trip and refuse bad input.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "model/file/model_json.h"
#include "model/model.h"
#include "support/model_document.h"

namespace implicitfit {
namespace {

using testsupport::ModelFromRoot;

TEST(CurveSkeleton, CircleTubeIsTheTorus) {
  const Model tube = ModelFromRoot(R"({"type": "skeleton_offset", "radius": 0.3, "skeleton":
      {"curve": {"ellipse": {"center": [0.1, -0.2, 0.3], "axes": [[1.5, 0, 0], [0, 1.5, 0]]}}}})");
  Model torus;
  torus.AddPrimitive(NodeType::kTorus, {0.1, -0.2, 0.3, 0, 0, 1, 1.5, 0.3});
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> box(-2.5, 2.5);
  double worst = 0.0;
  for (int i = 0; i < 1000; ++i) {
    const Eigen::Vector3d x(box(rng), box(rng), 0.5 * box(rng));
    worst = std::max(worst, std::abs(tube.Value(x) - torus.Value(x)));
  }
  EXPECT_LE(worst, 1e-12);
}

double BruteForce(const Model& m, const std::function<Eigen::Vector3d(double)>& curve, double t0,
                  double t1, const Eigen::Vector3d& x) {
  double best = INFINITY;
  for (int i = 0; i <= 100000; ++i)
    best = std::min(best, (curve(t0 + (t1 - t0) * i / 100000.0) - x).norm());
  return best - m.parameters().back();
}

TEST(CurveSkeleton, HelixAndEllipseDistancesMatchBruteForce) {
  const Model helix = ModelFromRoot(R"({"type": "skeleton_offset", "radius": 0.1, "skeleton":
      {"curve": {"helix": {"center": [0, 0, 0], "axes": [[1, 0, 0], [0, 0.8, 0.2]],
                           "rise": [0, 0, 0.7], "turns": 2.5}}}})");
  auto h = [](double t) {
    return Eigen::Vector3d(std::cos(2 * M_PI * t), 0.8 * std::sin(2 * M_PI * t),
                           0.2 * std::sin(2 * M_PI * t) + 0.7 * t);
  };
  const Model ellipse = ModelFromRoot(R"({"type": "skeleton_offset", "radius": 0.05, "skeleton":
      {"curve": {"ellipse": {"center": [1, 0, 0], "axes": [[2, 0, 0], [0.3, 0.5, 0.1]]}}}})");
  auto e = [](double t) {
    return Eigen::Vector3d(1 + 2 * std::cos(2 * M_PI * t) + 0.3 * std::sin(2 * M_PI * t),
                           0.5 * std::sin(2 * M_PI * t), 0.1 * std::sin(2 * M_PI * t));
  };
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> box(-2.0, 2.0);
  for (int i = 0; i < 12; ++i) {
    const Eigen::Vector3d x(box(rng), box(rng), 1 + box(rng));
    EXPECT_NEAR(helix.Value(x), BruteForce(helix, h, 0.0, 2.5, x), 2e-7) << x.transpose();
    const Eigen::Vector3d y(1 + 1.5 * box(rng), box(rng), 0.3 * box(rng));
    EXPECT_NEAR(ellipse.Value(y), BruteForce(ellipse, e, 0.0, 1.0, y), 2e-7) << y.transpose();
  }
}

TEST(CurveSkeleton, BezierIsTheClampedBSplineAndMatchesBruteForce) {
  const std::string points = R"([[0, 0, 0], [1, 2, 0], [2, -1, 1], [3, 0, 0]])";
  const Model bezier = ModelFromRoot(R"({"type": "skeleton_offset", "radius": 0.2, "skeleton":
      {"curve": {"bezier": {"control_points": )" +
                                     points + "}}}}");
  const Model bspline = ModelFromRoot(R"({"type": "skeleton_offset", "radius": 0.2, "skeleton":
      {"curve": {"bspline": {"degree": 3, "knots": [0, 0, 0, 0, 1, 1, 1, 1], "control_points": )" +
                                      points + "}}}}");
  auto c = [](double t) {
    const double s = 1 - t;
    return Eigen::Vector3d(s * s * s * 0 + 3 * s * s * t * 1 + 3 * s * t * t * 2 + t * t * t * 3,
                           3 * s * s * t * 2 + 3 * s * t * t * -1, 3 * s * t * t * 1);
  };
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> box(-1.0, 3.5);
  for (int i = 0; i < 25; ++i) {
    const Eigen::Vector3d x(box(rng), box(rng) - 1, box(rng) - 1);
    EXPECT_EQ(bezier.Value(x), bspline.Value(x));
    EXPECT_NEAR(bezier.Value(x), BruteForce(bezier, c, 0.0, 1.0, x), 2e-7) << x.transpose();
  }
  const Eigen::Vector3d x(1.2, 0.4, 0.9);
  const Eigen::Vector3d g = bezier.Gradient(x);
  const double h = 1e-6;
  for (int k = 0; k < 3; ++k)
    EXPECT_NEAR(g[k],
                (bezier.Value(x + h * Eigen::Vector3d::Unit(k)) -
                 bezier.Value(x - h * Eigen::Vector3d::Unit(k))) /
                    (2 * h),
                1e-6);
}

TEST(CurveSkeleton, JsonRoundTripsAndRefusals) {
  for (
      const std::string root :
      {R"({"type": "skeleton_offset", "radius": 0.2, "skeleton": {"curve": {"helix": {"center": [0, 0, 0], "axes": [[1, 0, 0], [0, 1, 0]], "rise": [0, 0, 1], "turns": 3}}}})",
       R"({"type": "skeleton_offset", "radius": 0.2, "skeleton": {"curve": {"bspline": {"degree": 2, "knots": [0, 0, 0, 1, 1, 1], "control_points": [[1, 0, 0], [1, 1, 0], [0, 1, 0]], "weights": [1, 0.7071067811865476, 1]}}}})",
       R"({"type": "skeleton_offset", "radius": 0.2, "skeleton": {"curve": {"ellipse": {"center": [0, 0, 0], "axes": [[1, 0, 0], [0, 2, 0]]}}}, "features": [{"point": [1.3, 0, 0], "width": 0.1, "depth": 0.05, "radius": 0.1, "flare": 0}]})"}) {
    const Model m = ModelFromRoot(root);
    const nlohmann::json j = ModelToJson(m);
    const Model back = ModelFromJson(j);
    EXPECT_EQ(back.parameters(), m.parameters());
    EXPECT_EQ(ModelToJson(back), j);
  }
  const Model segment = ModelFromRoot(
      R"({"type": "skeleton_offset", "radius": 0.2, "skeleton": {"curve": {"segment": [[0, 0, 0], [1, 0, 0]]}}})");
  EXPECT_NEAR(segment.Value(Eigen::Vector3d(0.5, 1, 0)), 0.8, 1e-15);
  for (
      const std::string bad :
      {R"({"curve": {"helix": {"center": [0, 0, 0], "axes": [[1, 0, 0], [0, 1, 0]], "rise": [0, 0, 1], "turns": 0}}})",
       R"({"curve": {"ellipse": {"center": [0, 0, 0], "axes": [[1, 0, 0], [2, 0, 0]]}}})",
       R"({"curve": {"bspline": {"degree": 3, "control_points": [[1, 0, 0], [1, 1, 0]]}}})",
       R"({"curve": {"bspline": {"degree": 1, "control_points": [[1, 0, 0], [1, 1, 0]], "weights": [1, 0]}}})",
       R"({"curve": {"spiral": {}}})",
       R"({"curve": {"bezier": {"control_points": [[1, 0, 0], [1, 1, 0]], "degree": 1}}})"}) {
    EXPECT_THROW(
        ModelFromRoot(R"({"type": "skeleton_offset", "radius": 0.2, "skeleton": )" + bad + "}"),
        ModelFormatError)
        << bad;
  }
}

}  // namespace
}  // namespace implicitfit
