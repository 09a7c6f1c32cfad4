// docs/maths.md JE-1 check 5: Jensen's example (a dome blended into a plane with known
// (a, b, c, d, theta)) sampled with 5000 points and noise 0.002; the fit of (a, b, theta) from a
// perturbed start recovers theta within 0.5 degrees and (a, b) within 1e-3.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "fit/splines/patch_tree_fit.h"
#include "support/dome_on_plane.h"

namespace implicitfit {
namespace {

TEST(PatchTreeFit, RecoversThePlacementOfADomeOnAPlane) {
  const double a = 0.3, b = -0.2, theta = 20.0 * M_PI / 180.0, sigma = 0.002;
  const PatchTree truth = testsupport::DomeOnPlane(a, b, theta);
  std::mt19937 rng(12);
  std::uniform_real_distribution<double> box(-2.0, 2.0);
  std::normal_distribution<double> noise(0.0, sigma);
  std::vector<Eigen::Vector3d> points;
  for (int i = 0; i < 5000; ++i) {
    double g[3];
    truth.Evaluate(truth.placements.data(), box(rng), box(rng), g);
    points.emplace_back(g[0] + noise(rng), g[1] + noise(rng), g[2] + noise(rng));
  }
  const PatchTree start = testsupport::DomeOnPlane(0.36, -0.25, 12.0 * M_PI / 180.0);
  const PatchTreeFitResult r = FitPatchTreePlacements(start, points);
  ASSERT_TRUE(r.success) << r.message;
  EXPECT_NEAR(r.placements[0], a, 1e-3);
  EXPECT_NEAR(r.placements[1], b, 1e-3);
  EXPECT_NEAR(r.placements[4] * 180.0 / M_PI, 20.0, 0.5);
  EXPECT_EQ(r.placements[2], 0.0);  // c, d held
  EXPECT_EQ(r.placements[3], 0.0);
  EXPECT_LT(r.rms, 2.0 * sigma);  // 3-D residual: sqrt(3) sigma at the optimum, less the fit
  EXPECT_GT(r.initial_rms, r.rms);
}

}  // namespace
}  // namespace implicitfit
