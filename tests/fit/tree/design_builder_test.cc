// Design from oriented points (docs/maths.md LP-3): the Fig. 8 analogue (four point/normal pairs of
// a square, z-extruded: each P_j on the zero set to 1e-12 with grad f parallel to n_j, once the
// precondition "every other child is below -(delta + epsilon) at P_j" is checked), and the
// builder on generated clouds: a box (its six face normals found, then fit --init to RMS <= 2
// sigma) and a paraboloid cap (kappa from the representatives within 10%, fit to RMS <= 2 sigma).
#include "fit/tree/design_builder.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <cstdio>

#include "datasets/generators/model_sampler.h"
#include "fit/tree/tree_fitter.h"

namespace implicitfit {
namespace {

using Vec = Eigen::Vector3d;

TEST(DesignBuilder, FourPointNormalPairsLieOnTheZeroSetWithTheirNormals) {
  const std::vector<OrientedRepresentative> reps = {{Vec(1, 0, 0), Vec(1, 0, 0)},
                                                    {Vec(0, 1, 0), Vec(0, 1, 0)},
                                                    {Vec(-1, 0, 0), Vec(-1, 0, 0)},
                                                    {Vec(0, -1, 0), Vec(0, -1, 0)}};
  DesignOptions o;
  o.delta = 0.2;
  o.epsilon = 0.1;
  const std::vector<double> base = {0, 0, 0, 3, 3, 3, 1, 0, 0, 0, 1, 0};
  const Model m = DesignModel(reps, base, o);
  ASSERT_EQ(m.nodes().size(), 6u);  // base, four planes, the intersection
  for (size_t j = 0; j < reps.size(); ++j) {
    // Precondition: every other child (base included) at least delta + epsilon below 0 at P_j.
    for (size_t i = 0; i + 1 < m.nodes().size(); ++i) {
      if (i == j + 1) continue;
      Model child;
      const ModelNode& node = m.nodes()[i];
      child.AddPrimitive(
          node.type,
          std::vector<double>(m.parameters().begin() + node.first_parameter,
                              m.parameters().begin() + node.first_parameter + node.num_parameters));
      ASSERT_LE(child.Value(reps[j].point), -(o.delta + o.epsilon)) << i << " at " << j;
    }
    double f;
    const Vec g = m.Gradient(reps[j].point, &f);
    EXPECT_NEAR(f, 0.0, 1e-12);
    EXPECT_LT((g.normalized() - reps[j].normal).norm(), 1e-12);
  }
}

TEST(DesignBuilder, BoxCloudGivesItsSixFacesAndFitsToTwoSigma) {
  const Eigen::Quaterniond q(Eigen::AngleAxisd(0.4, Vec(1, 2, 0.5).normalized()));
  Model truth;
  truth.AddPrimitive(NodeType::kBox, {0.1, -0.2, 0.3, q.w(), q.x(), q.y(), q.z(), 0.6, 0.4, 0.3});
  SampleOptions so;
  so.count = 1500;
  so.noise = 0.002;
  so.seed = 3;
  const SampledCloud s = SampleModel(truth, so);
  DesignOptions o;
  o.count = 6;
  const Model design = DesignFromOrientedPoints(s.cloud.points, s.cloud.normals, o);
  ASSERT_EQ(design.nodes().size(), 8u);
  const Eigen::Matrix3d r = q.toRotationMatrix();
  double worst_deg = 0;
  for (int face = 0; face < 6; ++face) {  // each face normal has a plane within a few degrees
    const Vec n = (face % 2 ? 1.0 : -1.0) * r.col(face / 2);
    double best = 180;
    for (int i = 1; i <= 6; ++i) {
      const double* p = design.parameters().data() + design.nodes()[i].first_parameter;
      best = std::min(
          best, std::acos(std::min(1.0, Vec(p[0], p[1], p[2]).normalized().dot(n))) * 180 / M_PI);
    }
    worst_deg = std::max(worst_deg, best);
  }
  const TreeFitResult fit = FitModelTree(design, s.cloud.points, s.cloud.normals, {});
  ASSERT_TRUE(fit.success) << fit.message;
  std::printf(
      "  design box: worst face normal of the design %.3f deg; fitted rms %.4g (sigma %g), %d "
      "iterations\n",
      worst_deg, fit.rms, so.noise, fit.iterations);
  EXPECT_LT(worst_deg, 5.0);
  EXPECT_LT(fit.rms, 2 * so.noise);
}

TEST(DesignBuilder, ParaboloidCapGivesItsCurvatureAndFitsToTwoSigma) {
  const Vec v(0.1, 0.2, -0.1), n = Vec(0.2, -0.1, 1).normalized();
  Model truth;
  truth.AddPrimitive(NodeType::kParaboloid, {v.x(), v.y(), v.z(), n.x(), n.y(), n.z(), 1.0});
  SampleOptions so;
  so.count = 3000;
  so.noise = 0.002;
  so.seed = 4;
  const SampledCloud s = SampleModel(truth, so);
  DesignOptions o;
  o.primitive = "paraboloid";
  o.count = 1;
  const Model design = DesignFromOrientedPoints(s.cloud.points, s.cloud.normals, o);
  const double* p = design.parameters().data() + design.nodes()[1].first_parameter;
  const double kappa = p[6];
  const TreeFitResult fit = FitModelTree(design, s.cloud.points, s.cloud.normals, {});
  ASSERT_TRUE(fit.success) << fit.message;
  std::printf("  design paraboloid: kappa %.4f (truth 1); fitted rms %.4g\n", kappa, fit.rms);
  EXPECT_NEAR(kappa, 1.0, 0.1);
  EXPECT_LT(fit.rms, 2 * so.noise);
}

}  // namespace
}  // namespace implicitfit
