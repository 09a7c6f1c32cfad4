// fit --init on a "smoothing": "convex" blend (docs/maths.md LP-4 b): the tree fitter recovers the
// two planes and the width w = delta of a rounded crease sampled from the truth; epsilon has no
// block (its slot is unused).
#include <gtest/gtest.h>

#include <cmath>

#include "datasets/generators/model_sampler.h"
#include "fit/tree/tree_fitter.h"
#include "fit/tree/tree_parameters.h"
#include "support/sample_in_box.h"

namespace implicitfit {
namespace {

using Vec = Eigen::Vector3d;

Model ConvexWedge(Vec n1, double d1, Vec n2, double d2, double w) {
  Model m;
  const int a = m.AddPrimitive(NodeType::kPlane, {n1.x(), n1.y(), n1.z(), d1});
  const int b = m.AddPrimitive(NodeType::kPlane, {n2.x(), n2.y(), n2.z(), d2});
  const int op = m.AddOperator(NodeType::kIntersection, {a, b}, w, w, 3);
  m.mutable_nodes()[op].smoothing = BlendSmoothing::kConvex;
  return m;
}

TEST(ConvexBlendFit, DeltaIsTheOnlyBlendBlock) {
  const Model m = ConvexWedge(Vec(0, 0, 1), 0, Vec(1, 0, 0), 0, 0.3);
  TreeParameters tp(m);
  EXPECT_EQ(tp.blocks().size(), 5u);  // normal, offset (x2), delta; no epsilon
  tp.blocks().back()[0] = std::log(0.7);
  EXPECT_NEAR(tp.ToFlat()[8], 0.7, 1e-15);
}

TEST(ConvexBlendFit, RecoversTwoPlanesAndTheWidthOfARoundedCrease) {
  const double w = 0.25;
  const Model truth = ConvexWedge(Vec(0, 0, 1), 0.0, Vec(1, 0, 0), 0.0, w);
  SampleOptions so = testsupport::SampleInBox(3000, 0.002, 4, Vec(-1, -1, -1), Vec(0.5, 1, 0.5));
  const SampledCloud s = SampleModel(truth, so);
  const Vec n1 = Vec(0.05, 0.03, 1).normalized(), n2 = Vec(1, -0.04, 0.06).normalized();
  const Model init = ConvexWedge(n1, 0.03, n2, -0.02, 0.4);
  const TreeFitResult r = FitModelTree(init, s.cloud.points, s.cloud.normals, TreeFitOptions{});
  ASSERT_TRUE(r.success) << r.message;
  const std::vector<double>& p = r.model.parameters();
  EXPECT_LT(std::acos(std::min(1.0, Vec(p[0], p[1], p[2]).normalized().z())), 2e-3);
  EXPECT_LT(std::acos(std::min(1.0, Vec(p[4], p[5], p[6]).normalized().x())), 2e-3);
  EXPECT_NEAR(p[8], w, 0.1 * w);
  EXPECT_EQ(r.model.nodes()[r.model.root()].smoothing, BlendSmoothing::kConvex);
  EXPECT_LT(r.rms, 1.5 * so.noise);
  std::printf("  convex blend: w %.4f (truth %.3f) rms %.5f\n", p[8], w, r.rms);
}

}  // namespace
}  // namespace implicitfit
