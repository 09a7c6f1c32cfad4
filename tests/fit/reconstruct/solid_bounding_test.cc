// Separators and closures of `reconstruct` (fit/reconstruct/solid_bounding.h), on data with known
// truth.
//   - BestStump against brute force over every threshold of every direction;
//   - SeparateCells: a cell holding a certain outside sample is outside whatever its votes;
//   - an open scan: a sharp box (half sizes 1, 0.7, 0.5) sampled without its bottom face gives a
//     bounded solid; exactly one closure is used, the bottom one, at the lowest seen point
//     minus the documented margin; the seen faces are the truth's; the sign of f agrees with
//     the truth at >= 99% of random points farther than 3% of the box from the truth surface
//     and above the unseen face by more than that;
//   - a cell that needs a separator: a ball on a stem (a cylinder standing on the plane z = 0,
//     ending inside the ball); the stem's cylinder also contains the space above the ball, in
//     the same cell of the arrangement of the three detected surfaces, so no expression over
//     them alone is bounded. One separator, a plane across the axis between the stem's foot and
//     the top of the ball, makes it so; the signs agree with the truth at >= 99% of random
//     points farther than 3% of the box from its surface, no closure is needed.
#include "fit/reconstruct/solid_bounding.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "datasets/generators/generated_solids.h"
#include "datasets/generators/model_sampler.h"
#include "fit/reconstruct/csg_separation.h"
#include "fit/reconstruct/solid_reconstruction.h"
#include "support/axis_box.h"
#include "support/sample_in_box.h"
#include "support/sign_agreement.h"

namespace implicitfit {
namespace {

using Vec = Eigen::Vector3d;

TEST(BestStump, MatchesBruteForce) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1, 1);
  const std::vector<Vec> directions = {Vec::UnitX(), Vec::UnitY(), Vec(1, 1, 0).normalized()};
  for (int trial = 0; trial < 20; ++trial) {
    std::vector<Vec> x;
    std::vector<bool> inside;
    const double c = 0.5 * u(rng);
    for (int i = 0; i < 60; ++i) {
      x.push_back(Vec(u(rng), u(rng), u(rng)));
      // inside below a diagonal line, with 10% of the labels flipped
      inside.push_back(((x.back().x() + x.back().y()) / std::sqrt(2.0) < c) != (i % 10 == 0));
    }
    int brute = 1 << 30;
    for (const Vec& d : directions)
      for (const Vec& p : x) {
        const double threshold = d.dot(p) + 1e-12;  // every split between two projections
        int left_in = 0, right_in = 0;
        for (size_t i = 0; i < x.size(); ++i) {
          const bool left = d.dot(x[i]) <= threshold;
          left_in += left != inside[i];
          right_in += left == inside[i];
        }
        brute = std::min({brute, left_in, right_in});
      }
    const StumpSplit split = BestStump(x, inside, directions);
    ASSERT_TRUE(split.found);
    EXPECT_EQ(split.errors, brute);
    int errors = 0;  // the plane's own count: inside samples on its f < 0 side
    for (size_t i = 0; i < x.size(); ++i)
      errors += (split.plane.normal.dot(x[i]) - split.plane.offset < 0) != inside[i];
    EXPECT_EQ(errors, split.errors);
  }
}

TEST(CsgSeparation, CertainOutsideSampleWins) {
  // Cell 0b01 has more inside votes, but one certain outside sample: it is outside.
  std::vector<CsgSample> samples;
  for (int i = 0; i < 5; ++i) {
    samples.push_back({0b01, true});
    samples.push_back({0b11, true});
    samples.push_back({0b00, false});
  }
  samples.push_back({0b01, false, false});
  // Not certain: cells 01 and 11 are inside, the solid is primitive 0.
  const CsgSeparation voted = SeparateCells(samples, 2);
  ASSERT_EQ(voted.terms.size(), 1u);
  EXPECT_EQ(voted.terms[0].inside, 0b01u);
  EXPECT_EQ(voted.terms[0].outside, 0u);
  // Certain: only cell 11 is inside; the term keeps primitive 1 (cell 10 is unseen, don't care).
  samples.back().certain = true;
  const CsgSeparation sep = SeparateCells(samples, 2);
  ASSERT_EQ(sep.terms.size(), 1u);
  EXPECT_EQ(sep.terms[0].inside, 0b10u);
  EXPECT_EQ(sep.terms[0].outside, 0u);
}

Model SharpBox(const Vec& half) { return testsupport::AxisBox(half, 0.01, 0.01, 0); }

TEST(SolidClosure, BoxScannedWithoutItsBottom) {
  const Vec half(1, 0.7, 0.5);
  const Model truth = SharpBox(half);
  const double size = 2 * half.maxCoeff();
  const double sigma = 0.002 * size;
  SampleOptions so = testsupport::SampleInBox(6000, sigma, 11, -1.2 * half, 1.2 * half);
  const SampledCloud sampled = SampleModel(truth, so);
  // The scan: every point but those of the bottom face (z = -0.5, outward normal -z).
  std::vector<Vec> points, normals;
  std::vector<int> labels;
  for (size_t i = 0; i < sampled.cloud.size(); ++i) {
    const Vec& p = sampled.cloud.points[i];
    const Vec& n = sampled.cloud.normals[i];
    if (n.z() < -0.9) continue;
    // label: the face (of the five seen) whose outward normal the point's normal is
    int label = -1;
    const int axis_of[5] = {0, 0, 1, 1, 2};
    const int sign_of[5] = {-1, 1, -1, 1, 1};
    for (int k = 0; k < 5; ++k)
      if (sign_of[k] * n[axis_of[k]] > 0.9 &&
          std::abs(sign_of[k] * p[axis_of[k]] - half[axis_of[k]]) < 4 * sigma)
        label = k;
    points.push_back(p);
    normals.push_back(n);
    labels.push_back(label);
  }
  const std::vector<NodeType> kinds(5, NodeType::kPlane);
  const std::vector<SolidPrimitive> scene =
      FitLabelledPrimitives(points, normals, labels, kinds, 11);
  SolidReconstructionOptions options;
  options.seed = 11;
  const SolidReconstruction r = ReconstructSolid(points, normals, scene, options);
  ASSERT_TRUE(r.success) << r.message << " expression " << r.expression;
  EXPECT_TRUE(r.bounded);
  std::printf("  expression %s, normal agreement %.4f\n", r.expression.c_str(), r.normal_agreement);
  ASSERT_EQ(r.closures.size(), 1u);
  const AddedPlane& closure = r.closures[0];
  EXPECT_GT(-closure.normal.z(), 0.9999);  // the unseen bottom face
  // Its position: the lowest seen point (the side faces end at z = -0.5, noise sigma) lowered
  // by the margin, 2% of the cloud's diagonal.
  Vec lo = points[0], hi = points[0];
  for (const Vec& p : points) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  const double expected = -half.z() - options.closure_margin * (hi - lo).norm();
  EXPECT_NEAR(-closure.offset / -closure.normal.z(), expected, 5 * sigma);
  EXPECT_TRUE(r.separators.empty());
  EXPECT_GE(r.normal_agreement, 0.99);

  // Signs on the seen part: farther than 3% of the box from the truth surface, and above the
  // bottom face by more than that.
  const Vec box_lo = -1.2 * half, box_hi = 1.2 * half;
  const double away = 0.03 * (box_hi - box_lo).maxCoeff();
  const double share =
      testsupport::SignAgreement(truth, r.model, box_lo, box_hi, away, 11,
                                 [&](const Vec& x) { return x.z() >= -half.z() + away; });
  std::printf("  closure z %.4f (expected %.4f), sign agreement on the seen part %.4f\n",
              -closure.offset / -closure.normal.z(), expected, share);
  EXPECT_GE(share, 0.99);
}

TEST(SolidSeparator, BallOnStem) {
  // Ball: centre (0, 0, 1.5), radius 0.8; stem: radius 0.35 along z, from z = 0 to the centre.
  Model truth;
  const int ball = truth.AddPrimitive(NodeType::kSphere, {0, 0, 1.5, 0.8});
  const int cylinder = truth.AddPrimitive(NodeType::kCylinder, {0, 0, 0, 0, 0, 1, 0.35});
  const int foot = truth.AddPrimitive(NodeType::kPlane, {0, 0, -1, 0});
  const int cap = truth.AddPrimitive(NodeType::kPlane, {0, 0, 1, 1.5});
  const int stem = truth.AddOperator(NodeType::kIntersection, {cylinder, foot, cap}, 0.01, 0.01, 0);
  truth.SetRoot(truth.AddOperator(NodeType::kUnion, {ball, stem}, 0.01, 0.01, 0));
  const Vec box_lo(-1, -1, -0.2), box_hi(1, 1, 2.5);
  const double sigma = 0.002 * (box_hi - box_lo).maxCoeff();
  SampleOptions so = testsupport::SampleInBox(6000, sigma, 12, box_lo, box_hi);
  const SampledCloud sampled = SampleModel(truth, so);
  // Labels: the detected surface (ball 0, cylinder 1, foot 2) within 4 sigma with its normal.
  std::vector<int> labels;
  for (size_t i = 0; i < sampled.cloud.size(); ++i) {
    const Vec& p = sampled.cloud.points[i];
    const Vec& n = sampled.cloud.normals[i];
    const Vec radial = (p - Vec(0, 0, 1.5)).normalized();
    const Vec out(p.x(), p.y(), 0);
    int label = -1;
    if (std::abs((p - Vec(0, 0, 1.5)).norm() - 0.8) < 4 * sigma && n.dot(radial) > 0.99) label = 0;
    if (std::abs(out.norm() - 0.35) < 4 * sigma && n.dot(out.normalized()) > 0.99) label = 1;
    if (std::abs(p.z()) < 4 * sigma && n.z() < -0.99) label = 2;
    labels.push_back(label);
  }
  const std::vector<NodeType> kinds = {NodeType::kSphere, NodeType::kCylinder, NodeType::kPlane};
  const std::vector<SolidPrimitive> scene =
      FitLabelledPrimitives(sampled.cloud.points, sampled.cloud.normals, labels, kinds, 12);
  SolidReconstructionOptions options;
  options.seed = 12;
  const SolidReconstruction r =
      ReconstructSolid(sampled.cloud.points, sampled.cloud.normals, scene, options);
  ASSERT_TRUE(r.success) << r.message << " expression " << r.expression;
  std::printf("  expression %s\n", r.expression.c_str());
  EXPECT_TRUE(r.closures.empty());
  ASSERT_GE(r.separators.size(), 1u);
  for (const AddedPlane& s : r.separators) {
    EXPECT_GT(std::abs(s.normal.z()), 0.9999);  // across the axis
    const double z = s.offset / s.normal.z();
    std::printf("  separator at z = %.4f\n", z);
    EXPECT_GT(z, 0.0);
    EXPECT_LT(z, 2.3);
  }
  const double away = 0.03 * (box_hi - box_lo).maxCoeff();
  const double share = testsupport::SignAgreement(truth, r.model, box_lo, box_hi, away, 12);
  std::printf("  sign agreement %.4f\n", share);
  EXPECT_GE(share, 0.99);
}

}  // namespace
}  // namespace implicitfit
