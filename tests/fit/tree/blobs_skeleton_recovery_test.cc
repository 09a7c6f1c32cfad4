// Recovery of blobs (docs/maths.md TB-2 test 3) and of a capsule skeleton offset (CO-1 test 2)
// through the tree fitter, from clouds sampled on the true models.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "datasets/generators/model_sampler.h"
#include "fit/tree/tree_fitter.h"
#include "support/capsule.h"
#include "support/cramer_rao.h"

namespace implicitfit {
namespace {

using Vec = Eigen::Vector3d;
using testsupport::Capsule;

// Three Gaussian blobs with noise-free samples, started 0.05 off in every centre and 10% off in
// every weight and width: the fit must land on the truth (centres within 1e-6 of the blob
// spacing).
TEST(BlobsRecovery, ThreeGaussianBlobsFromAPerturbedStart) {
  const std::vector<double> centres = {-0.6, 0, 0, 0.6, 0, 0, 0, 0.7, 0.2};
  const std::vector<double> weights = {2.0, 1.8, 1.6}, widths = {3.0, 3.5, 4.0};
  Model truth;
  truth.AddBlobs(BlobKernel::kGaussian, 0, centres, weights, widths, 1.0);
  SampleOptions so;
  so.count = 3000;
  so.seed = 12;
  const SampledCloud s = SampleModel(truth, so);
  std::vector<double> c0 = centres, w0 = weights, b0 = widths;
  const double shifts[9] = {0.05, -0.03, 0.04, -0.04, 0.05, -0.02, 0.03, -0.05, 0.04};
  for (int i = 0; i < 9; ++i) c0[i] += shifts[i];
  for (int i = 0; i < 3; ++i) w0[i] *= i % 2 ? 0.9 : 1.1, b0[i] *= i % 2 ? 1.1 : 0.9;
  Model init;
  init.AddBlobs(BlobKernel::kGaussian, 0, c0, w0, b0, 1.0);
  const TreeFitResult r = FitModelTree(init, s.cloud.points, s.cloud.normals, TreeFitOptions{});
  ASSERT_TRUE(r.success) << r.message;
  const std::vector<double>& p = r.model.parameters();
  double worst = 0;
  for (int i = 0; i < 9; ++i) worst = std::max(worst, std::abs(p[i] - centres[i]));
  std::printf(
      "  3 blobs: worst centre error %.3g (spacing 1.2), weights %.6f %.6f %.6f, threshold %.3f\n",
      worst, p[9], p[10], p[11], p[15]);
  EXPECT_LT(worst, 1e-6 * 1.2);
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(p[9 + i], weights[i], 1e-5 * weights[i]);
    EXPECT_NEAR(p[12 + i], widths[i], 1e-5 * widths[i]);
  }
  EXPECT_EQ(p[15], 1.0);  // the threshold fixes the scale: never fitted
}

// A capsule sampled with noise and outliers: end points and radius within 2.5 Cramer-Rao
// spreads (numerical bound from the exact distance of the true capsule at the inliers).
TEST(SkeletonOffsetRecovery, CapsuleEndPointsAndRadiusWithinTwoAndAHalfCramerRaoSpreads) {
  const Vec a(-0.5, 0.1, 0.0), b(0.6, -0.2, 0.3);
  const double radius = 0.3;
  SampleOptions so;
  so.count = 5000;
  so.noise = 0.002;
  so.outlier_fraction = 0.2;
  so.seed = 14;
  const SampledCloud s = SampleModel(Capsule(a, b, radius), so);
  const TreeFitResult r =
      FitModelTree(Capsule(a + Vec(0.03, -0.02, 0.03), b + Vec(-0.03, 0.03, 0.02), 1.1 * radius),
                   s.cloud.points, s.cloud.normals, TreeFitOptions{});
  ASSERT_TRUE(r.success) << r.message;
  const std::vector<double>& p = r.model.parameters();
  const Vec a_hat(p[0], p[1], p[2]), b_hat(p[3], p[4], p[5]);
  std::vector<Vec> inliers;
  for (size_t i = 0; i < s.cloud.points.size(); ++i)
    if (!s.is_outlier[i]) inliers.push_back(s.cloud.points[i]);
  const auto residual = [&](const Eigen::VectorXd& d, const Vec& x) {
    return Capsule(a + d.segment<3>(0), b + d.segment<3>(3), radius + d[6]).Value(x);
  };
  const Eigen::MatrixXd cov = testsupport::CramerRaoCovariance(residual, 7, inliers, so.noise);
  const double sa = testsupport::Spread(cov, 0, 3), sb = testsupport::Spread(cov, 3, 3),
               sr = std::sqrt(cov(6, 6));
  std::printf(
      "  capsule: end errors %.3g, %.3g (CR spreads %.3g, %.3g), radius %.3g (%.3g), rms %.4g\n",
      (a_hat - a).norm(), (b_hat - b).norm(), sa, sb, std::abs(p[6] - radius), sr, r.rms);
  EXPECT_LT((a_hat - a).norm(), 2.5 * sa);
  EXPECT_LT((b_hat - b).norm(), 2.5 * sb);
  EXPECT_LT(std::abs(p[6] - radius), 2.5 * sr);
}

}  // namespace
}  // namespace implicitfit
