// fit --model bspline-volume (fit/splines/bspline_volume_fitter.h): a torus sampled with noise is
// fitted with its zero set close to the torus everywhere (no spurious sheet: the fitted zero
// set sampled and measured with the torus's exact distance), the right signs in the hole and in
// the tube; a convex fit to an ellipsoid is certified convex and within the noise.
#include <gtest/gtest.h>

#include <cmath>

#include "datasets/generators/model_sampler.h"
#include "fit/splines/bspline_volume_fitter.h"

namespace implicitfit {
namespace {

double TruthRms(const Model& fitted, const Model& truth, double* worst) {
  SampleOptions o;
  o.count = 1500;
  o.seed = 3;
  const SampledCloud on = SampleModel(fitted, o);
  double sum = 0.0;
  *worst = 0.0;
  for (const Eigen::Vector3d& x : on.cloud.points) {
    const double d = truth.Value(x);
    sum += d * d;
    *worst = std::max(*worst, std::abs(d));
  }
  return std::sqrt(sum / on.cloud.points.size());
}

TEST(BSplineVolumeFit, TorusWithinTheNoiseAndNoSpuriousSheet) {
  Model torus;
  torus.AddPrimitive(NodeType::kTorus, {0, 0, 0, 0, 0, 1, 1.0, 0.35});
  SampleOptions so;
  so.count = 4000;
  so.noise = 0.002;
  so.seed = 5;
  const SampledCloud cloud = SampleModel(torus, so);
  VolumeFitOptions o;
  o.cells = 12;
  const VolumeFitResult r = FitBSplineVolume(cloud.cloud.points, cloud.cloud.normals, o);
  ASSERT_TRUE(r.success) << r.message;
  const Model m = r.ToModel();
  EXPECT_GT(m.Value(Eigen::Vector3d(0, 0, 0)), 0.0);      // the hole
  EXPECT_LT(m.Value(Eigen::Vector3d(1, 0, 0)), 0.0);      // the tube's core
  EXPECT_LT(m.Value(Eigen::Vector3d(0, -1, 0.1)), 0.0);
  EXPECT_GT(m.Value(Eigen::Vector3d(0, 0, 0.8)), 0.0);    // above the hole
  double worst;
  const double truth = TruthRms(m, torus, &worst);
  EXPECT_LE(truth, 0.004) << "worst " << worst;
  EXPECT_LE(worst, 0.02);
  EXPECT_LE(r.rms, 0.004);
  RecordProperty("torus_truth_rms", std::to_string(truth));
}

TEST(BSplineVolumeFit, ConvexEllipsoidIsCertified) {
  Model ellipsoid;
  ellipsoid.AddPrimitive(NodeType::kEllipsoid, {0.1, 0, -0.2, 1.0, 0.7, 0.5, 1, 0, 0, 0, 1, 0});
  SampleOptions so;
  so.count = 3000;
  so.noise = 0.002;
  so.seed = 6;
  const SampledCloud cloud = SampleModel(ellipsoid, so);
  VolumeFitOptions o;
  o.cells = 4;
  o.convex = true;
  const VolumeFitResult r = FitBSplineVolume(cloud.cloud.points, cloud.cloud.normals, o);
  ASSERT_TRUE(r.success) << r.message;
  EXPECT_TRUE(r.certified_convex);
  EXPECT_TRUE(CertifyVolumeConvexity(r.structure, r.coefficients.data()).convex);
  EXPECT_GT(r.certificate.min_eigenvalue, 0.0);
  EXPECT_LE(r.rms, 0.003);
  EXPECT_GE(r.unconstrained_rms, 0.0);
  double worst;
  EXPECT_LE(TruthRms(r.ToModel(), ellipsoid, &worst), 0.003);
  VolumeFitOptions linear = o;
  linear.degree = 1;
  EXPECT_FALSE(FitBSplineVolume(cloud.cloud.points, cloud.cloud.normals, linear).success);
}

}  // namespace
}  // namespace implicitfit
