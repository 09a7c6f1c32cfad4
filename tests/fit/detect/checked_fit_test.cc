// fit --model KIND on clouds of many surfaces (fit/detect/checked_fit.h): a real primitive of the
// kind or a refusal, never a confident wrong one; and the fixed threshold's meaning.
// Truth: the generated scenes' own primitives and labels (datasets/generators/scene_generator.h),
// and brute-force inlier counts from the returned parameters.
#include "fit/detect/checked_fit.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "datasets/generators/scene_generator.h"
#include "datasets/normals/neighbourhoods.h"
#include "fit/primitive/primitive_function.h"

namespace implicitfit {
namespace {

// RMS over truth primitive g's labelled points of the fitted model's distance.
double RmsOverTruth(const GeneratedScene& s, int g, const Model& fitted) {
  double ss = 0;
  int n = 0;
  for (size_t i = 0; i < s.labels.size(); ++i)
    if (s.labels[i] == g) ss += std::pow(fitted.Value(s.cloud.points[i]), 2), ++n;
  return std::sqrt(ss / n);
}

TEST(CheckedFit, OnGeneratedScenesEachKindIsATruePrimitiveOrRefused) {
  const double noise = 0.005;
  int accepted = 0, total = 0;
  for (unsigned seed = 1; seed <= 3; ++seed) {
    GeneratedSceneOptions o;
    o.seed = seed;
    o.noise = noise;
    const GeneratedScene s = GenerateScene(o);
    const Neighbourhoods nb = FindNeighbourhoods(s.cloud.points);
    for (NodeType kind : {NodeType::kPlane, NodeType::kSphere, NodeType::kCylinder,
                          NodeType::kCone, NodeType::kTorus}) {
      PrimitiveFitOptions fo;
      fo.kind = kind;
      fo.seed = seed;
      const CheckedFit c =
          FitCheckedPrimitive(s.cloud.points, s.cloud.normals, nb.indices, nb.spacing, fo);
      ++total;
      EXPECT_TRUE(c.checked);
      if (!c.result.success) {
        // A refusal names the kind and says why.
        EXPECT_NE(c.result.message.find(std::string("no ") + NodeTypeName(kind)),
                  std::string::npos)
            << c.result.message;
        continue;
      }
      ++accepted;
      // The accepted model lies on one of the scene's primitives of that kind: its distance
      // over that primitive's points is the noise (a wrong surface crossing the band, or a
      // primitive of another kind, leaves several times more).
      const Model fitted = c.result.ToModel(kind);
      double best = INFINITY;
      for (size_t g = 0; g < s.kinds.size(); ++g)
        if (s.kinds[g] == kind) best = std::min(best, RmsOverTruth(s, static_cast<int>(g), fitted));
      EXPECT_LT(best, 2.0 * noise) << NodeTypeName(kind) << " seed " << seed << " source "
                                   << c.source;
    }
  }
  // The checks do not refuse everything: most kinds are found on most scenes.
  EXPECT_GE(accepted, total * 2 / 3) << accepted << " of " << total;
}

TEST(CheckedFit, ATorusOnASphereIsRefusedAsASphere) {
  // A full sphere is a torus of major radius 0; the kind check names the simpler kind.
  std::mt19937 rng(3);
  std::normal_distribution<double> g(0, 1);
  std::vector<Eigen::Vector3d> p, n;
  for (int i = 0; i < 3000; ++i) {
    const Eigen::Vector3d u = Eigen::Vector3d(g(rng), g(rng), g(rng)).normalized();
    p.push_back(Eigen::Vector3d(1, 2, 3) + (2.0 + 0.002 * g(rng)) * u);
    n.push_back(u);
  }
  const Neighbourhoods nb = FindNeighbourhoods(p);
  PrimitiveFitOptions fo;
  fo.kind = NodeType::kTorus;
  const CheckedFit c = FitCheckedPrimitive(p, n, nb.indices, nb.spacing, fo);
  EXPECT_FALSE(c.result.success);
  EXPECT_NE(c.result.message.find("no torus explains"), std::string::npos) << c.result.message;
  fo.kind = NodeType::kSphere;
  const CheckedFit s = FitCheckedPrimitive(p, n, nb.indices, nb.spacing, fo);
  ASSERT_TRUE(s.result.success) << s.result.message;
  EXPECT_EQ(s.first_check, "passed");
  EXPECT_NEAR(s.result.parameters[3], 2.0, 0.002);
}

TEST(CheckedFit, AFixedThresholdIsTheInlierDistanceOfEveryRound) {
  // A noisy sphere with outliers: with threshold t the inliers are exactly the points within t
  // whose normals agree (|cos| >= 0.8), counted here from the returned parameters.
  std::mt19937 rng(5);
  std::normal_distribution<double> g(0, 1);
  std::uniform_real_distribution<double> u(-2, 2);
  std::vector<Eigen::Vector3d> p, n;
  for (int i = 0; i < 4000; ++i) {
    const Eigen::Vector3d d = Eigen::Vector3d(g(rng), g(rng), g(rng)).normalized();
    p.push_back((1.0 + 0.01 * g(rng)) * d);
    n.push_back(d);
  }
  for (int i = 0; i < 400; ++i) {
    p.push_back(Eigen::Vector3d(u(rng), u(rng), u(rng)));
    n.push_back(Eigen::Vector3d(g(rng), g(rng), g(rng)).normalized());
  }
  for (double t : {0.005, 0.05}) {
    PrimitiveFitOptions fo;
    fo.kind = NodeType::kSphere;
    fo.threshold = t;
    const PrimitiveFitResult r = FitPrimitive(p, n, fo);
    ASSERT_TRUE(r.success) << r.message;
    const PrimitiveFunction f(NodeType::kSphere, r.parameters);
    size_t expected = 0;
    for (size_t i = 0; i < p.size(); ++i) {
      Eigen::Vector3d grad;
      const double v = f(p[i], &grad);
      expected += std::abs(v) < t && std::abs(grad.normalized().dot(n[i])) >= 0.8;
    }
    EXPECT_EQ(r.inliers.size(), expected) << t;
    EXPECT_LT(r.max_abs, t);
  }
  // The adaptive band, started at the tight threshold, grows to 3 sigma (sigma 0.01): more
  // inliers than the fixed 0.005.
  PrimitiveFitOptions fixed, adaptive;
  fixed.kind = adaptive.kind = NodeType::kSphere;
  fixed.threshold = 0.005;
  adaptive.start_band = 0.005;
  EXPECT_GT(FitPrimitive(p, n, adaptive).inliers.size(),
            FitPrimitive(p, n, fixed).inliers.size() + 1000);
}

}  // namespace
}  // namespace implicitfit
