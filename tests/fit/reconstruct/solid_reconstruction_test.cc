// reconstruct on generated solids (issue 14): the truth is a smooth-CSG model, sampled with
// noise sigma = 0.2% of its size and 5% outliers; the scene is built from ground-truth labels
// (a point belongs to the truth primitive it lies on, fillet points to none) with each
// primitive fitted to its points by the primitive fitter, as `detect` would. Checks, against
// the truth only: RMS first-order distance at noise-free truth points <= 3 sigma; sign of f
// agrees with the truth at >= 99% of random points of the enlarged box farther than 3% of its
// size from the truth surface; every fillet radius within 10% of the truth's.
#include "fit/reconstruct/solid_reconstruction.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "datasets/generators/generated_solids.h"
#include "datasets/generators/model_sampler.h"
#include "fit/reconstruct/csg_separation.h"
#include "support/sign_agreement.h"

namespace implicitfit {
namespace {

using Vec = Eigen::Vector3d;

void CheckReconstruction(const GeneratedSolid& solid, unsigned seed) {
  const double size = (solid.box_max - solid.box_min).maxCoeff();
  const double sigma = 0.002 * size;
  SampleOptions so;
  so.count = 6000;
  so.noise = sigma;
  so.outlier_fraction = 0.05;
  so.seed = seed;
  so.has_box = true;
  so.box_min = solid.box_min;
  so.box_max = solid.box_max;
  const SampledCloud cloud = SampleModel(solid.truth, so);

  // Scene from ground-truth labels: the truth primitive within 4 sigma whose normal matches.
  const std::vector<int> labels = GroundTruthLabels(solid, cloud.cloud, 4 * sigma);
  std::vector<int> inlier_labels = labels;  // the outliers' truth: they belong to no primitive
  for (size_t i = 0; i < labels.size(); ++i)
    if (cloud.is_outlier[i]) inlier_labels[i] = -1;
  std::vector<NodeType> kinds;
  for (const Model& p : solid.primitives) kinds.push_back(p.nodes()[0].type);
  const std::vector<SolidPrimitive> scene =
      FitLabelledPrimitives(cloud.cloud.points, cloud.cloud.normals, inlier_labels, kinds, seed);
  SolidReconstructionOptions options;
  options.seed = seed;
  const SolidReconstruction r =
      ReconstructSolid(cloud.cloud.points, cloud.cloud.normals, scene, options);
  ASSERT_TRUE(r.success) << r.message << " expression " << r.expression;
  std::printf("  expression %s  rms %.5f (sigma %.5f)  normal agreement %.4f  %.1f s\n",
              r.expression.c_str(), r.rms, sigma, r.normal_agreement, r.seconds);

  // RMS first-order distance at noise-free truth points.
  SampleOptions clean = so;
  clean.noise = 0;
  clean.outlier_fraction = 0;
  clean.count = 3000;
  clean.seed = seed + 100;
  const SampledCloud truth_points = SampleModel(solid.truth, clean);
  double sum2 = 0;
  for (const Vec& x : truth_points.cloud.points) {
    double f;
    const Vec g = r.model.Gradient(x, &f);
    sum2 += f * f / g.squaredNorm();
  }
  const double rms = std::sqrt(sum2 / truth_points.cloud.size());
  EXPECT_LE(rms, 3 * sigma);

  // Sign agreement away from the surface.
  const Vec lo = solid.box_min - 0.1 * (solid.box_max - solid.box_min);
  const Vec hi = solid.box_max + 0.1 * (solid.box_max - solid.box_min);
  const double sign_share =
      testsupport::SignAgreement(solid.truth, r.model, lo, hi, 0.03 * (hi - lo).maxCoeff(), seed);
  EXPECT_GE(sign_share, 0.99);

  // Fillets: one smooth blend, its radius within 10% of the truth's (creases at 90 degrees).
  for (const BlendEstimate& e : r.blends)
    std::printf("  blend %s %s delta %.4f eps %.4f, %d transition points\n", e.node.c_str(),
                e.type.c_str(), e.delta, e.epsilon, e.transition_points);
  ASSERT_EQ(r.blends.size(), 1u);
  const BlendEstimate& b = r.blends[0];
  const double truth_radius = solid.fillet_delta / (4 * (1 - std::cos(M_PI / 4)));
  EXPECT_NEAR(b.crease_angle_deg, 90.0, 5.0);
  EXPECT_NEAR(b.fillet_radius, truth_radius, 0.1 * truth_radius);
  EXPECT_GT(b.sd_delta, 0.0);
  EXPECT_LT(b.sd_delta, 0.1 * b.delta);
  std::printf(
      "  truth-point rms %.5f  sign agreement %.4f  blend %s delta %.4f +- %.4f eps %.4f +- %.4f "
      "radius %.4f (truth %.4f), %d transition points\n",
      rms, sign_share, b.type.c_str(), b.delta, b.sd_delta, b.epsilon, b.sd_epsilon,
      b.fillet_radius, truth_radius, b.transition_points);
}

TEST(SolidReconstruction, RoundedBox) { CheckReconstruction(RoundedBoxSolid(), 3); }
TEST(SolidReconstruction, PlateWithFilletedBore) {
  CheckReconstruction(PlateWithFilletedBoreSolid(), 4);
}
TEST(SolidReconstruction, BossOnSlab) { CheckReconstruction(BossOnSlabSolid(), 5); }

// The separation alone: a box minus a hole from labelled cells (exact Boolean algebra).
TEST(CsgSeparation, BoxMinusHoleFromCells) {
  // Primitives: 0 = box, 1 = hole. Inside: box & !hole. Outside: !box (both), box & hole.
  std::vector<CsgSample> samples;
  for (int i = 0; i < 5; ++i) {
    samples.push_back({0b01, true});
    samples.push_back({0b11, false});
    samples.push_back({0b00, false});
    samples.push_back({0b10, false});
  }
  const CsgSeparation sep = SeparateCells(samples, 2);
  ASSERT_EQ(sep.terms.size(), 1u);
  EXPECT_EQ(sep.terms[0].inside, 0b01u);
  EXPECT_EQ(sep.terms[0].outside, 0b10u);
  EXPECT_EQ(CsgExpressionText(sep.terms, {"box", "hole"}), "(box & !hole)");
}

}  // namespace
}  // namespace implicitfit
