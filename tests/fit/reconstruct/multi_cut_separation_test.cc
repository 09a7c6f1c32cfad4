// A cell that needs several separators (Fit4CAD PC131), in a generated solid with known truth: a
// slab 0 < z < 0.5 whose four bottom edges are quarter-round cylinders of radius 0.5 (axes along
// x and y at |y| = 1.3 or |x| = 1.3, z = 0.5) meeting at corner spheres (centres (+-1.3, +-1.3,
// 0.5)); the top face spans |x|, |y| < 1.8, the bottom face |x|, |y| < 1.3. No detected surface
// lies on the planes |x| = 1.3, |y| = 1.3 that bound the slab's centre, which therefore shares
// its sign vector (below the top, above the bottom, outside every round) with the space beyond
// the four sides: one cell with many inside and many outside samples, which no single plane
// halves. Checked: reconstruct finds a bounded solid, with separators (one per side), and its
// sign agrees with the truth at >= 99% of random points of the box farther than 3% of its size
// from the truth surface.
#include <gtest/gtest.h>

#include <cmath>

#include "datasets/generators/model_sampler.h"
#include "fit/reconstruct/solid_reconstruction.h"
#include "support/sample_in_box.h"
#include "support/sign_agreement.h"

namespace implicitfit {
namespace {

using Vec = Eigen::Vector3d;

TEST(MultiCutSeparation, SlabWithRoundedEdges) {
  const double a = 1.3, h = 0.5;
  Model truth;
  auto plane = [&](const Vec& n, double d) {
    return truth.AddPrimitive(NodeType::kPlane, {n.x(), n.y(), n.z(), d});
  };
  std::vector<int> parts;
  parts.push_back(
      truth.AddOperator(NodeType::kIntersection,
                        {plane(Vec::UnitZ(), h), plane(-Vec::UnitZ(), 0), plane(Vec::UnitX(), a),
                         plane(-Vec::UnitX(), a), plane(Vec::UnitY(), a), plane(-Vec::UnitY(), a)},
                        0.01, 0.01, 0));
  for (int axis = 0; axis < 2; ++axis)
    for (int s : {-1, 1}) {
      Vec point(0, 0, h), along = Vec::Zero();
      point[1 - axis] = s * a;
      along[axis] = 1;
      const int bar = truth.AddPrimitive(NodeType::kCylinder, {point.x(), point.y(), point.z(),
                                                               along.x(), along.y(), along.z(), h});
      parts.push_back(truth.AddOperator(
          NodeType::kIntersection, {bar, plane(Vec::UnitZ(), h), plane(along, a), plane(-along, a)},
          0.01, 0.01, 0));
    }
  for (int sx : {-1, 1})
    for (int sy : {-1, 1}) {
      const int ball = truth.AddPrimitive(NodeType::kSphere, {sx * a, sy * a, h, h});
      parts.push_back(truth.AddOperator(NodeType::kIntersection, {ball, plane(Vec::UnitZ(), h)},
                                        0.01, 0.01, 0));
    }
  truth.SetRoot(truth.AddOperator(NodeType::kUnion, parts, 0.01, 0.01, 0));

  const Vec box_lo(-2.1, -2.1, -0.3), box_hi(2.1, 2.1, 0.8);
  const double size = 2 * (a + h);
  const double sigma = 0.002 * size;
  SampleOptions so = testsupport::SampleInBox(12000, sigma, 41, box_lo, box_hi);
  const SampledCloud sampled = SampleModel(truth, so);
  // Scene: top 0, bottom 1, rounds 2-5 (x bars at y = -a, +a, then y bars at x = -a, +a),
  // corners 6-9; labels: the truth surface within 4 sigma whose outward normal matches.
  std::vector<int> labels;
  for (size_t i = 0; i < sampled.cloud.size(); ++i) {
    const Vec& p = sampled.cloud.points[i];
    const Vec& n = sampled.cloud.normals[i];
    int label = -1;
    if (std::abs(p.z() - h) < 4 * sigma && n.z() > 0.99) label = 0;
    if (std::abs(p.z()) < 4 * sigma && n.z() < -0.99) label = 1;
    int k = 2;
    for (int axis = 0; axis < 2; ++axis)
      for (int s : {-1, 1}) {
        Vec c(0, 0, h);
        c[1 - axis] = s * a;
        Vec d = p - c;
        d[axis] = 0;
        if (std::abs(d.norm() - h) < 4 * sigma && n.dot(d.normalized()) > 0.99 &&
            std::abs(p[axis]) < a)
          label = k;
        ++k;
      }
    for (int sx : {-1, 1})
      for (int sy : {-1, 1}) {
        const Vec d = p - Vec(sx * a, sy * a, h);
        if (std::abs(d.norm() - h) < 4 * sigma && n.dot(d.normalized()) > 0.99 && sx * p.x() > a &&
            sy * p.y() > a)
          label = k;
        ++k;
      }
    labels.push_back(label);
  }
  std::vector<NodeType> kinds = {NodeType::kPlane, NodeType::kPlane};
  kinds.insert(kinds.end(), 4, NodeType::kCylinder);
  kinds.insert(kinds.end(), 4, NodeType::kSphere);
  const std::vector<SolidPrimitive> scene =
      FitLabelledPrimitives(sampled.cloud.points, sampled.cloud.normals, labels, kinds, 41);
  SolidReconstructionOptions options;
  options.seed = 41;
  const SolidReconstruction r =
      ReconstructSolid(sampled.cloud.points, sampled.cloud.normals, scene, options);
  ASSERT_TRUE(r.success) << r.message << " expression " << r.expression;
  std::printf("  expression %s\n  %zu separators, %zu closures\n", r.expression.c_str(),
              r.separators.size(), r.closures.size());
  EXPECT_TRUE(r.closures.empty());
  EXPECT_GE(r.separators.size(), 2u);
  const double away = 0.03 * (box_hi - box_lo).maxCoeff();
  const double share = testsupport::SignAgreement(truth, r.model, box_lo, box_hi, away, 41);
  std::printf("  sign agreement %.4f\n", share);
  EXPECT_GE(share, 0.99);
}

}  // namespace
}  // namespace implicitfit
