// fit/reconstruct/unsupported_repair.h on the verifier's own refusals: a box minus a ball the
// cloud never saw (an unsupported cavity) is filled back to the box, a box with a far ball no
// point lies on loses the ball; the expected results are the box itself (the cloud's truth),
// checked by f's sign at the cavity's and the ball's centres and by the verification. A swapped
// inside (not a matter of unsupported pieces) is left alone.
#include "fit/reconstruct/unsupported_repair.h"

#include <gtest/gtest.h>

#include "datasets/generators/model_sampler.h"
#include "support/sample_in_box.h"

namespace implicitfit {
namespace {

using Vec = Eigen::Vector3d;

int AddBox(Model* m, const Vec& half, const std::string& prefix) {
  std::vector<int> faces;
  for (int a = 0; a < 3; ++a)
    for (int s : {-1, 1}) {
      const Vec n = s * Vec::Unit(a);
      faces.push_back(m->AddPrimitive(NodeType::kPlane, {n.x(), n.y(), n.z(), half[a]},
                                      prefix + std::to_string(faces.size())));
    }
  return m->AddOperator(NodeType::kIntersection, faces, 0.1, 0.1, 0);
}

PointCloud BoxCloud() {
  Model box;
  box.SetRoot(AddBox(&box, Vec(1, 0.7, 0.5), "p"));
  SampleOptions so =
      testsupport::SampleInBox(4000, 0.004, 5, Vec::Constant(-1.5), Vec::Constant(1.5));
  return SampleModel(box, so).cloud;
}

TEST(UnsupportedRepair, FillsACavityAndCutsAFarPiece) {
  const PointCloud cloud = BoxCloud();
  for (const bool cavity : {true, false}) {
    Model m;
    const int box = AddBox(&m, Vec(1, 0.7, 0.5), "p");
    const Vec centre = cavity ? Vec(0.2, 0, 0) : Vec(3, 0, 0);
    const int ball =
        m.AddPrimitive(NodeType::kSphere, {centre.x(), centre.y(), centre.z(), 0.3}, "ball");
    m.SetRoot(
        m.AddOperator(cavity ? NodeType::kDifference : NodeType::kUnion, {box, ball}, 0.1, 0.1, 0));
    SolidVerification v = VerifySolid(m, cloud.points, cloud.normals);
    ASSERT_FALSE(v.verified);
    ASSERT_FALSE(v.pieces_supported);
    EXPECT_EQ(m.Value(centre) > 0, cavity);  // the cavity is empty, the far ball material
    const PieceRepair r = RepairUnsupportedPieces(&m, &v, cloud.points, cloud.normals, {});
    EXPECT_TRUE(r.verified) << r.message;
    EXPECT_TRUE(v.verified) << v.message;
    EXPECT_EQ(r.filled, cavity ? 1 : 0);
    EXPECT_EQ(r.removed, cavity ? 0 : 1);
    // the box itself: material at the cavity's centre, none at the far ball's
    if (cavity)
      EXPECT_LT(m.Value(centre), 0);
    else
      EXPECT_GT(m.Value(centre), 0);
    EXPECT_EQ(v.components.solids, 1);
    EXPECT_EQ(v.components.cavities, 0);
  }
}

TEST(UnsupportedRepair, LeavesOtherFailuresAlone) {
  const PointCloud cloud = BoxCloud();
  Model m;
  const int outer = AddBox(&m, Vec(1.5, 1.2, 1.0), "outer");
  const int inner = AddBox(&m, Vec(1, 0.7, 0.5), "p");
  m.SetRoot(m.AddOperator(NodeType::kDifference, {outer, inner}, 0.1, 0.1, 0));
  const Model before = m;
  SolidVerification v = VerifySolid(m, cloud.points, cloud.normals);
  ASSERT_FALSE(v.verified);
  const PieceRepair r = RepairUnsupportedPieces(&m, &v, cloud.points, cloud.normals, {});
  EXPECT_FALSE(r.verified);
  EXPECT_EQ(r.rounds, 0);
  EXPECT_EQ(m.nodes().size(), before.nodes().size());
}

}  // namespace
}  // namespace implicitfit
