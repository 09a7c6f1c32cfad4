// The figures a primitive fit reports (rms, max |f|, mean normal angle) recomputed here from the
// returned parameters and inliers through the model (model/model.h), not the fitter's code.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "datasets/generators/model_sampler.h"
#include "fit/primitive/primitive_fitter.h"

namespace implicitfit {
namespace {

TEST(PrimitiveFitFigures, MatchTheModelAtTheReturnedParameters) {
  struct Case {
    NodeType kind;
    std::vector<double> truth;
  };
  const Case cases[] = {{NodeType::kSphere, {1.0, -2.0, 0.5, 1.5}},
                        {NodeType::kCone, {0.1, 0.2, 0.3, -0.3, 0.4, 1.0, 0.5}}};
  for (const Case& c : cases) {
    Model truth;
    truth.AddPrimitive(c.kind, c.truth);
    SampleOptions so;
    so.count = 4000;
    so.noise = 0.01;
    so.outlier_fraction = 0.1;
    so.seed = 3;
    SampledCloud s = SampleModel(truth, so);
    std::mt19937 rng(5);  // a few degrees of normal noise, so the mean angle is not ~0
    std::normal_distribution<double> noise(0.0, 0.05);
    for (auto& n : s.cloud.normals)
      n = (n + Eigen::Vector3d(noise(rng), noise(rng), noise(rng))).normalized();
    PrimitiveFitOptions o;
    o.kind = c.kind;
    const PrimitiveFitResult r = FitPrimitive(s.cloud.points, s.cloud.normals, o);
    ASSERT_TRUE(r.success) << r.message;
    ASSERT_FALSE(r.inliers.empty());
    const Model fitted = r.ToModel(c.kind);
    double ss = 0, max_abs = 0, angles = 0;
    for (int i : r.inliers) {
      double f = 0;
      const Eigen::Vector3d g = fitted.Gradient(s.cloud.points[i], &f);
      ss += f * f;
      max_abs = std::max(max_abs, std::abs(f));
      const double cosine =
          std::abs(g.dot(s.cloud.normals[i])) / (g.norm() * s.cloud.normals[i].norm());
      angles += std::acos(std::min(1.0, cosine)) * 180.0 / M_PI;
    }
    const double n = static_cast<double>(r.inliers.size());
    EXPECT_NEAR(r.rms, std::sqrt(ss / n), 1e-9);
    EXPECT_NEAR(r.max_abs, max_abs, 1e-9);
    EXPECT_NEAR(r.mean_normal_angle_deg, angles / n, 1e-5);
    EXPECT_GT(r.mean_normal_angle_deg, 1.0);
  }
}

}  // namespace
}  // namespace implicitfit
