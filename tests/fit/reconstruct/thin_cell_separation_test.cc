// A cell of the arrangement thinner than the inside/outside samples' fixed offset
// (fit/reconstruct/offset_samples.h), the situation of Fit4CAD PC34's flange rim, in a generated
// solid with known truth: a dome (sphere of centre (0, 0, -0.5) through the circle r = 1, z = 0.05)
// cut by the cylinder r = 1 about z and standing on the plane z = 0. The cylinder bounds a rim 0.05
// high; the material it removes from the sphere is a sliver at most 0.0259 wide (at z = 0:
// sqrt(R^2 - 0.25) - 1), thinner than t = 1% of the cloud's diagonal (0.029). With the fixed
// offset, the rim's outside samples land beyond the sphere, the sliver's cell gets none and the
// cylinder is dropped: the solid bulges by up to 0.0259 (6.5 sigma) there. With the adaptive
// offset the cylinder must be in the expression and every noise-free truth point (rim included)
// within 3 sigma of the result's zero set (first-order distance |f| / |grad f|).
#include <gtest/gtest.h>

#include <cmath>

#include "datasets/generators/model_sampler.h"
#include "fit/reconstruct/solid_reconstruction.h"
#include "support/sample_in_box.h"

namespace implicitfit {
namespace {

using Vec = Eigen::Vector3d;

TEST(ThinCell, DomeWithNarrowRim) {
  const double rim = 0.05, centre = -0.5;
  const double radius = std::sqrt(1 + (rim - centre) * (rim - centre));
  Model truth;
  const int sphere = truth.AddPrimitive(NodeType::kSphere, {0, 0, centre, radius});
  const int cylinder = truth.AddPrimitive(NodeType::kCylinder, {0, 0, 0, 0, 0, 1, 1.0});
  const int base = truth.AddPrimitive(NodeType::kPlane, {0, 0, -1, 0});
  truth.SetRoot(
      truth.AddOperator(NodeType::kIntersection, {sphere, cylinder, base}, 0.01, 0.01, 0));
  const Vec box_lo(-1.2, -1.2, -0.2), box_hi(1.2, 1.2, 0.8);
  const double size = 2.0;  // the solid's largest extent
  const double sigma = 0.002 * size;
  SampleOptions so = testsupport::SampleInBox(6000, sigma, 21, box_lo, box_hi);
  const SampledCloud sampled = SampleModel(truth, so);
  // Labels: sphere 0, cylinder 1, base 2: the truth surface within 4 sigma, normal matching.
  std::vector<int> labels;
  int rim_points = 0;
  for (size_t i = 0; i < sampled.cloud.size(); ++i) {
    const Vec& p = sampled.cloud.points[i];
    const Vec& n = sampled.cloud.normals[i];
    const Vec radial = (p - Vec(0, 0, centre)).normalized();
    const Vec out = Vec(p.x(), p.y(), 0).normalized();
    int label = -1;
    if (std::abs((p - Vec(0, 0, centre)).norm() - radius) < 4 * sigma && n.dot(radial) > 0.99)
      label = 0;
    if (std::abs(Vec(p.x(), p.y(), 0).norm() - 1) < 4 * sigma && n.dot(out) > 0.99) label = 1;
    if (std::abs(p.z()) < 4 * sigma && n.z() < -0.99) label = 2;
    rim_points += label == 1;
    labels.push_back(label);
  }
  ASSERT_GE(rim_points, 60);
  const std::vector<NodeType> kinds = {NodeType::kSphere, NodeType::kCylinder, NodeType::kPlane};
  const std::vector<SolidPrimitive> scene =
      FitLabelledPrimitives(sampled.cloud.points, sampled.cloud.normals, labels, kinds, 21);
  // Noise-free truth points, the rim's among them.
  SampleOptions clean = so;
  clean.noise = 0;
  clean.seed = 22;
  const std::vector<Vec> truth_points = SampleModel(truth, clean).cloud.points;
  auto largest_distance = [&](const Model& m, bool rim_only) {
    double largest = 0;
    for (const Vec& x : truth_points) {
      if (rim_only && !(x.z() < rim && Vec(x.x(), x.y(), 0).norm() > 1 - 1e-6)) continue;
      double f;
      const Vec g = m.Gradient(x, &f);
      largest = std::max(largest, std::abs(f) / g.norm());
    }
    return largest;
  };
  double fixed_rim = 0, adaptive_rim = 0;
  for (const bool adaptive : {false, true}) {
    SolidReconstructionOptions options;
    options.seed = 21;
    options.adaptive_offset = adaptive;
    const SolidReconstruction r =
        ReconstructSolid(sampled.cloud.points, sampled.cloud.normals, scene, options);
    ASSERT_TRUE(r.success) << r.message << " expression " << r.expression;
    const double on_rim = largest_distance(r.model, true);
    const double anywhere = largest_distance(r.model, false);
    std::printf(
        "  %s offset: expression %s, largest distance of the truth points %.5f (rim %.5f, "
        "3 sigma %.4f)\n",
        adaptive ? "adaptive" : "fixed", r.expression.c_str(), anywhere, on_rim, 3 * sigma);
    (adaptive ? adaptive_rim : fixed_rim) = on_rim;
    if (adaptive) {
      EXPECT_NE(r.expression.find("p1"), std::string::npos) << r.expression;
      EXPECT_LE(anywhere, 3 * sigma);
    }
  }
  // The case is the one the adaptive offset is for: the fixed offset loses the rim.
  EXPECT_GT(fixed_rim, 3 * sigma);
  EXPECT_LT(adaptive_rim, fixed_rim);
}

}  // namespace
}  // namespace implicitfit
