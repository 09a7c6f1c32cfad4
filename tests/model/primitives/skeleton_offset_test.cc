// Skeleton offsets (docs/maths.md CO-1): one point is the sphere bit for bit, a capsule's distances
// in closed form, a polyline is the union of its segments' capsules, and the JSON forms.
#include <gtest/gtest.h>

#include <random>

#include "model/file/model_json.h"
#include "model/model.h"
#include "support/model_document.h"

namespace implicitfit {
namespace {

using Vec = Eigen::Vector3d;

using testsupport::ModelFromRoot;

TEST(SkeletonOffset, SinglePointIsTheSphereBitForBit) {
  Model sphere;
  sphere.AddPrimitive(NodeType::kSphere, {0.3, -0.7, 1.1, 0.9});
  const Model point = ModelFromRoot(
      R"({"type": "skeleton_offset", "skeleton": {"points": [[0.3, -0.7, 1.1]]}, "radius": 0.9})");
  std::mt19937 rng(8);
  std::uniform_real_distribution<double> u(-3, 3);
  for (int i = 0; i < 1000; ++i) {
    const Vec x(u(rng), u(rng), u(rng));
    EXPECT_EQ(point.Value(x), sphere.Value(x));
    EXPECT_EQ(point.Gradient(x), sphere.Gradient(x));
  }
}

TEST(SkeletonOffset, CapsuleDistancesInClosedForm) {
  // Segment from (0,0,0) to (0,0,2), radius 0.5.
  const Model m = ModelFromRoot(
      R"({"type": "skeleton_offset", "skeleton": {"segments": [[[0, 0, 0], [0, 0, 2]]]}, "radius": 0.5})");
  EXPECT_DOUBLE_EQ(m.Value(Vec(3, 4, 1)), 5.0 - 0.5);    // beside the segment: radial distance
  EXPECT_DOUBLE_EQ(m.Value(Vec(0, 0, 3)), 1.0 - 0.5);    // beyond the end cap
  EXPECT_DOUBLE_EQ(m.Value(Vec(0, 3, -4)), 5.0 - 0.5);   // below the start: distance to (0,0,0)
  EXPECT_DOUBLE_EQ(m.Value(Vec(0, 0.1, 1)), 0.1 - 0.5);  // inside
}

TEST(SkeletonOffset, PolylineIsTheUnionOfItsSegmentCapsules) {
  const Model poly = ModelFromRoot(
      R"({"type": "skeleton_offset", "skeleton": {"polyline": [[0, 0, 0], [1, 0, 0], [1, 1, 0], [1, 1, 1]]}, "radius": 0.2})");
  const Model segs =
      ModelFromRoot(R"({"type": "skeleton_offset", "skeleton": {"segments": [[[0, 0, 0], [1, 0, 0]],
      [[1, 0, 0], [1, 1, 0]], [[1, 1, 0], [1, 1, 1]]]}, "radius": 0.2})");
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> u(-1, 2);
  for (int i = 0; i < 500; ++i) {
    const Vec x(u(rng), u(rng), u(rng));
    EXPECT_EQ(poly.Value(x), segs.Value(x));
    // Brute force: the distance to 3000 points along the polyline bounds it from above.
    double best = 1e300;
    const Vec v[4] = {Vec(0, 0, 0), Vec(1, 0, 0), Vec(1, 1, 0), Vec(1, 1, 1)};
    for (int s = 0; s < 3; ++s)
      for (int k = 0; k <= 1000; ++k)
        best = std::min(best, (x - (v[s] + (v[s + 1] - v[s]) * (k / 1000.0))).norm());
    EXPECT_LE(poly.Value(x), best - 0.2 + 1e-15);
    EXPECT_GE(poly.Value(x), best - 0.2 - 1e-3);
  }
  EXPECT_EQ(ModelToJson(ModelFromJson(ModelToJson(poly))), ModelToJson(poly));
  EXPECT_EQ(ModelToJson(ModelFromJson(ModelToJson(segs))), ModelToJson(segs));
}

TEST(SkeletonOffset, RefusesEmptyOrAmbiguousSkeletons) {
  EXPECT_THROW(
      ModelFromRoot(R"({"type": "skeleton_offset", "skeleton": {"points": []}, "radius": 1})"),
      ModelFormatError);
  EXPECT_THROW(
      ModelFromRoot(
          R"({"type": "skeleton_offset", "skeleton": {"polyline": [[0, 0, 0]]}, "radius": 1})"),
      ModelFormatError);
  EXPECT_THROW(
      ModelFromRoot(
          R"({"type": "skeleton_offset", "skeleton": {"points": [[0, 0, 0]], "polyline": [[0, 0, 0], [1, 0, 0]]}, "radius": 1})"),
      ModelFormatError);
  EXPECT_THROW(
      ModelFromRoot(
          R"({"type": "skeleton_offset", "skeleton": {"points": [[0, 0, 0]]}, "radius": -1})"),
      ModelFormatError);
  // Triangles (docs/maths.md CO-1's surface skeleton) load; a triangle needs three corners, and an
  // unknown skeleton kind is refused.
  EXPECT_NO_THROW(ModelFromRoot(
      R"({"type": "skeleton_offset", "skeleton": {"triangles": [[[0, 0, 0], [1, 0, 0], [0, 1, 0]]]}, "radius": 1})"));
  EXPECT_THROW(
      ModelFromRoot(
          R"({"type": "skeleton_offset", "skeleton": {"triangles": [[[0, 0, 0], [1, 0, 0]]]}, "radius": 1})"),
      ModelFormatError);
  EXPECT_THROW(
      ModelFromRoot(
          R"({"type": "skeleton_offset", "skeleton": {"surfaces": [[0, 0, 0]]}, "radius": 1})"),
      ModelFormatError);
}

}  // namespace
}  // namespace implicitfit
