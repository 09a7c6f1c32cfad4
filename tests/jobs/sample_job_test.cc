// The sample job on a sphere, through the public header only: the points' distances to the
// sphere are the requested noise (bounded, with the right spread), their normals radial.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "implicitfit/model.h"
#include "implicitfit/sample.h"

namespace implicitfit {
namespace {

const Eigen::Vector3d kCentre(1.0, -2.0, 0.5);
constexpr double kRadius = 2.0;

Model Sphere() {
  Model m;
  m.AddPrimitive(NodeType::kSphere, {kCentre.x(), kCentre.y(), kCentre.z(), kRadius});
  return m;
}

// |x - c| - r: the signed distance to the sphere, not the model's f.
double Distance(const Eigen::Vector3d& x) { return (x - kCentre).norm() - kRadius; }

TEST(SampleJob, NoiseFreePointsLieOnTheSphere) {
  SampleJobOptions options;
  options.sample.count = 2000;
  options.sample.seed = 3;
  const SampleJobResult job = SampleModelJob(Sphere(), options);
  ASSERT_TRUE(job.success) << job.message;
  ASSERT_EQ(job.sampled.cloud.size(), 2000u);
  for (size_t i = 0; i < job.sampled.cloud.size(); ++i) {
    const Eigen::Vector3d& x = job.sampled.cloud.points[i];
    // The projection stops at |f| < 1e-12 (1 + |x|_inf); |x|_inf <= 4.5 here.
    EXPECT_LE(std::abs(Distance(x)), 1e-10) << "point " << i;
    EXPECT_LT((job.sampled.cloud.normals[i] - (x - kCentre).normalized()).norm(), 1e-8);
    EXPECT_EQ(job.sampled.primitive[i], 0);  // the one leaf
  }
  ASSERT_EQ(job.truth_kinds.size(), 1u);
  EXPECT_EQ(job.truth_kinds[0], NodeType::kSphere);
}

TEST(SampleJob, NoisyPointsStayWithinTheNoiseBound) {
  const double sigma = 0.01;
  const int n = 4000;
  SampleJobOptions options;
  options.sample.count = n;
  options.sample.noise = sigma;
  options.sample.seed = 5;
  std::string error;
  ASSERT_TRUE(options.IsValid(&error)) << error;
  const SampleJobResult job = SampleModelJob(Sphere(), options);
  ASSERT_TRUE(job.success) << job.message;
  ASSERT_EQ(job.sampled.cloud.size(), static_cast<size_t>(n));
  // Gaussian displacement of sigma along the normal: |f| <= 6 sigma for every point fails with
  // probability n P(|Z| > 6) = 4000 x 2e-9 < 1e-5; the RMS estimates sigma with relative
  // standard error 1 / sqrt(2 n) = 1.1%, so 10% is 9 standard errors.
  double sum2 = 0;
  for (const Eigen::Vector3d& x : job.sampled.cloud.points) {
    const double f = Distance(x);
    EXPECT_LE(std::abs(f), 6 * sigma);
    sum2 += f * f;
  }
  const double rms = std::sqrt(sum2 / n);
  EXPECT_NEAR(rms, sigma, 0.1 * sigma);
  const nlohmann::json report = job.ToJson();
  EXPECT_EQ(report["job"], "sample");
  EXPECT_EQ(report["points"], n);
  EXPECT_EQ(report["outliers"], 0);
  EXPECT_EQ(report["settings"]["noise"], sigma);
}

TEST(SampleJob, InvalidOptionsAreRefused) {
  SampleJobOptions options;
  options.sample.noise = -1;
  std::string error;
  EXPECT_FALSE(options.IsValid(&error));
  EXPECT_EQ(error.rfind("noise", 0), 0u) << error;
  EXPECT_THROW(SampleModelJob(Sphere(), options), std::invalid_argument);
}

}  // namespace
}  // namespace implicitfit
