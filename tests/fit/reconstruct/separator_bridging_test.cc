// fit/reconstruct/separator_bridging.h on a hand-built dome on a slab whose dome term is cut by a
// separator 0.1 above the slab (PC155's failure): two solid pieces, both supported, so the
// verification passes; replacing the separator by the slab's bottom plane gives the truth
// (sphere & bottom) | slab, one piece. The expected result comes from the construction.
#include "fit/reconstruct/separator_bridging.h"

#include <gtest/gtest.h>

#include "datasets/generators/model_sampler.h"
#include "support/sample_in_box.h"

namespace implicitfit {
namespace {

using Vec = Eigen::Vector3d;

// slab |x|, |y| <= 1, -0.5 <= z <= 0 (planes p0..p5, p4 its bottom) united with the ball of
// radius 0.6 about the origin cut by the plane `cut` (material z >= cut_z).
Model DomeOnSlab(const std::string& cut, double cut_z) {
  Model m;
  std::vector<int> faces;
  const Vec normals[6] = {-Vec::UnitX(), Vec::UnitX(),  -Vec::UnitY(),
                          Vec::UnitY(),  -Vec::UnitZ(), Vec::UnitZ()};
  const double offsets[6] = {1, 1, 1, 1, 0.5, 0};
  for (int k = 0; k < 6; ++k)
    faces.push_back(m.AddPrimitive(NodeType::kPlane,
                                   {normals[k].x(), normals[k].y(), normals[k].z(), offsets[k]},
                                   "p" + std::to_string(k)));
  const int slab = m.AddOperator(NodeType::kIntersection, faces, 0.1, 0.1, 0);
  const int ball = m.AddPrimitive(NodeType::kSphere, {0, 0, 0, 0.6}, "p6");
  const int plane = m.AddPrimitive(NodeType::kPlane, {0, 0, -1, -cut_z}, cut);
  const int dome = m.AddOperator(NodeType::kIntersection, {ball, plane}, 0.1, 0.1, 0);
  m.SetRoot(m.AddOperator(NodeType::kUnion, {slab, dome}, 0.1, 0.1, 0));
  return m;
}

TEST(SeparatorBridging, JoinsADomeCutOffItsSlabByAMisplacedSeparator) {
  const Model truth = DomeOnSlab("p4", -0.5);
  SampleOptions so =
      testsupport::SampleInBox(6000, 0.004, 3, Vec(-1.2, -1.2, -0.7), Vec(1.2, 1.2, 0.8));
  const PointCloud cloud = SampleModel(truth, so).cloud;
  SolidVerificationOptions vo;
  vo.num_threads = 2;
  Model model = DomeOnSlab("separator0", 0.1);
  SolidVerification v = VerifySolid(model, cloud.points, cloud.normals, vo);
  ASSERT_TRUE(v.verified) << v.message;
  ASSERT_EQ(v.components.solids, 2) << v.message;

  const SeparatorBridging b = BridgeSeparatedPieces(&model, &v, cloud.points, cloud.normals, vo);
  ASSERT_EQ(b.replaced.size(), 1u);
  EXPECT_EQ(b.replaced[0].first, "separator0");
  EXPECT_TRUE(v.verified) << v.message;
  EXPECT_EQ(v.components.solids, 1) << v.message;
  // the bridged dome reaches down into the slab: material just above and below z = 0 on the axis
  EXPECT_LT(model.Value(Vec(0, 0, 0.05)), 0);
  EXPECT_LT(model.Value(Vec(0, 0, 0.4)), 0);
  EXPECT_GT(model.Value(Vec(0, 0, 0.7)), 0);
  EXPECT_GT(model.Value(Vec(0, 0, -0.7)), 0);  // nothing below the slab
  EXPECT_EQ(b.replaced[0].second, "p4");       // the bottom: the only plane that joins and verifies
  EXPECT_EQ(RenameInExpression("(p6 & separator0) | (separator01 & p0)", "separator0", "p4"),
            "(p6 & p4) | (separator01 & p0)");
}

}  // namespace
}  // namespace implicitfit
