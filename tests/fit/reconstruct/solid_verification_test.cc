// fit/reconstruct/solid_verification.h on hand-built trees and clouds sampled from known
// solids (datasets/generators/model_sampler.h, outward normals, noise 0.2% of the size):
// accepted are a box of six planes and a cylinder with caps sampled from themselves; refused,
// each for its own reason, are a single plane, a solid with an infinite tube (PC34's failure),
// a box with an enclosed cavity no point lies on, a box with a far piece no point lies on, and
// a shell whose inside is the data's outside. The expected verdicts come from the construction
// (the cloud is the truth's surface), not from the verifier.
#include "fit/reconstruct/solid_verification.h"

#include <gtest/gtest.h>

#include <cmath>

#include "datasets/generators/model_sampler.h"
#include "support/sample_in_box.h"

namespace implicitfit {
namespace {

using Vec = Eigen::Vector3d;

int AddPlane(Model* m, const Vec& n, double d, const std::string& name) {
  return m->AddPrimitive(NodeType::kPlane, {n.x(), n.y(), n.z(), d}, name);
}

// Box |x| <= hx, |y| <= hy, |z| <= hz as an intersection of six named planes (f: Li & Phillips,
// sharp).
int AddBox(Model* m, const Vec& half, const Vec& centre, const std::string& prefix) {
  std::vector<int> faces;
  for (int a = 0; a < 3; ++a)
    for (int s : {-1, 1}) {
      const Vec n = s * Vec::Unit(a);
      faces.push_back(
          AddPlane(m, n, n.dot(centre) + half[a], prefix + std::to_string(faces.size())));
    }
  return m->AddOperator(NodeType::kIntersection, faces, 0.1, 0.1, 0);
}

Model BoxModel() {
  Model m;
  m.SetRoot(AddBox(&m, Vec(1, 0.7, 0.5), Vec::Zero(), "p"));
  return m;
}

PointCloud Sample(const Model& truth, const Vec& lo, const Vec& hi, int count = 4000) {
  SampleOptions so = testsupport::SampleInBox(count, 0.002 * (hi - lo).maxCoeff(), 5, lo, hi);
  return SampleModel(truth, so).cloud;
}

bool Mentions(const SolidVerification& v, const std::string& what) {
  return v.message.find(what) != std::string::npos;
}

TEST(SolidVerification, AcceptsABoxOfSixPlanes) {
  const Model box = BoxModel();
  const PointCloud cloud = Sample(box, Vec(-1.5, -1.5, -1.5), Vec(1.5, 1.5, 1.5));
  const SolidVerification v = VerifySolid(box, cloud.points, cloud.normals);
  EXPECT_TRUE(v.verified) << v.message;
  ASSERT_TRUE(v.bounded);
  // The bounds are the box itself (six half-spaces: the polyhedron is the box).
  EXPECT_NEAR(v.bounds_max.x(), 1.0, 1e-6);
  EXPECT_NEAR(v.bounds_min.y(), -0.7, 1e-6);
  EXPECT_NEAR(v.bounds_max.z(), 0.5, 1e-6);
  EXPECT_GE(v.agreement, 0.99);
  EXPECT_EQ(v.components.solids, 1);
  EXPECT_EQ(v.components.cavities, 0);
  ASSERT_EQ(v.primitives.size(), 6u);
  for (const PrimitiveAgreement& p : v.primitives) {
    EXPECT_TRUE(p.checked) << p.name;
    EXPECT_GE(p.agreement, 0.95) << p.name;
  }
  // The claims written into a model.
  Model claimed = box;
  ClaimVerification(v, &claimed);
  EXPECT_TRUE(claimed.claims().has_bounds);
  EXPECT_TRUE(claimed.claims().verified);
}

TEST(SolidVerification, AcceptsACylinderWithCaps) {
  Model m;
  const int side = m.AddPrimitive(NodeType::kCylinder, {0, 0, 0, 0, 0, 1, 0.6}, "side");
  const int top = AddPlane(&m, Vec::UnitZ(), 1.0, "top");
  const int bottom = AddPlane(&m, -Vec::UnitZ(), 1.0, "bottom");
  m.SetRoot(m.AddOperator(NodeType::kIntersection, {side, top, bottom}, 0.1, 0.1, 0));
  const PointCloud cloud = Sample(m, Vec(-1, -1, -1.5), Vec(1, 1, 1.5));
  const SolidVerification v = VerifySolid(m, cloud.points, cloud.normals);
  EXPECT_TRUE(v.verified) << v.message;
  EXPECT_NEAR(v.bounds_max.z(), 1.0, 1e-6);
  EXPECT_LE(v.bounds_max.x(), 0.6 / std::cos(M_PI / 8) + 1e-6);
  EXPECT_EQ(v.components.solids, 1);
}

TEST(SolidVerification, ProvesATubeBoundedByTheConeThatSwallowsIt) {
  // A tube r = 1 above z = 0 minus a cone (apex (0, 0, 1), axis +z, 60 degrees): the cone's
  // radius passes 1 at z = 1 + 1 / tan(60 deg) = 1.577, so the solid ends there. The tube's
  // polyhedron alone is unbounded; only the split on the cone's outside proves it.
  Model m;
  const int side = m.AddPrimitive(NodeType::kCylinder, {0, 0, 0, 0, 0, 1, 1.0}, "side");
  const int floor = AddPlane(&m, -Vec::UnitZ(), 0.0, "floor");
  const int tube = m.AddOperator(NodeType::kIntersection, {side, floor}, 0.1, 0.1, 0);
  const int cone = m.AddPrimitive(NodeType::kCone, {0, 0, 1, 0, 0, 1, M_PI / 3}, "cone");
  m.SetRoot(m.AddOperator(NodeType::kDifference, {tube, cone}, 0.1, 0.1, 0));
  const PointCloud cloud = Sample(m, Vec(-1.5, -1.5, -0.5), Vec(1.5, 1.5, 2.0));
  const SolidVerification v = VerifySolid(m, cloud.points, cloud.normals);
  ASSERT_TRUE(v.bounded) << v.message;
  EXPECT_GT(v.split_pieces, 0);
  EXPECT_GE(v.bounds_max.z(), 1 + 1 / std::tan(M_PI / 3));
  EXPECT_LE(v.bounds_max.z(), 3.0);
  // independently: f > 0 on the axis above the bounds and at random far points
  for (double z = v.bounds_max.z() + 1e-6; z < 1e4; z *= 2)
    EXPECT_GT(m.Value(Vec(0, 0, z)), 0) << z;
  EXPECT_TRUE(v.verified) << v.message;
}

TEST(SolidVerification, RefusesASinglePlane) {
  Model plane;
  plane.SetRoot(AddPlane(&plane, Vec::UnitZ(), 0.0, "p0"));
  // points on the square |x|, |y| <= 1 of the plane, normals up (outward of z <= 0)
  std::vector<Vec> points, normals;
  for (int i = 0; i <= 40; ++i)
    for (int j = 0; j <= 40; ++j) {
      points.push_back(Vec(-1 + i / 20.0, -1 + j / 20.0, 0));
      normals.push_back(Vec::UnitZ());
    }
  const SolidVerification v = VerifySolid(plane, points, normals);
  EXPECT_FALSE(v.verified);
  EXPECT_FALSE(v.bounded);
  EXPECT_TRUE(Mentions(v, "not bounded")) << v.message;
  EXPECT_LE(v.unbounded_witness_value, 0);  // the half-space truly reaches infinity
}

TEST(SolidVerification, RefusesASolidWithAnInfiniteTube) {
  // A capped cylinder united with a tube open upwards (PC34: f(0, 0, 300) < 0); the cloud is
  // the capped cylinder's surface, which the tube also passes through.
  Model m;
  const int side = m.AddPrimitive(NodeType::kCylinder, {0, 0, 0, 0, 0, 1, 0.6}, "side");
  const int top = AddPlane(&m, Vec::UnitZ(), 1.0, "top");
  const int bottom = AddPlane(&m, -Vec::UnitZ(), 1.0, "bottom");
  const int solid = m.AddOperator(NodeType::kIntersection, {side, top, bottom}, 0.1, 0.1, 0);
  Model capped = m;
  capped.SetRoot(solid);
  const int tube = m.AddPrimitive(NodeType::kCylinder, {0, 0, 0, 0, 0, 1, 0.3}, "tube");
  const int floor = AddPlane(&m, -Vec::UnitZ(), -0.5, "floor");  // z >= 0.5
  const int term = m.AddOperator(NodeType::kIntersection, {tube, floor}, 0.1, 0.1, 0);
  m.SetRoot(m.AddOperator(NodeType::kUnion, {solid, term}, 0.1, 0.1, 0));
  ASSERT_LT(m.Value(Vec(0, 0, 300)), 0);
  const PointCloud cloud = Sample(capped, Vec(-1, -1, -1.5), Vec(1, 1, 1.5));
  const SolidVerification v = VerifySolid(m, cloud.points, cloud.normals);
  EXPECT_FALSE(v.verified);
  EXPECT_FALSE(v.bounded);
  EXPECT_NE(v.unbounded_piece.find("tube"), std::string::npos) << v.unbounded_piece;
  EXPECT_GT(v.unbounded_direction.z(), 0);
  EXPECT_TRUE(Mentions(v, "not bounded")) << v.message;
}

TEST(SolidVerification, RefusesAnUnsupportedCavity) {
  // The box minus a sphere inside it (radius 0.3): bounded, the cloud is the box's surface only,
  // so the cavity's shell carries no point.
  Model m;
  const int box = AddBox(&m, Vec(1, 0.7, 0.5), Vec::Zero(), "p");
  const int hole = m.AddPrimitive(NodeType::kSphere, {0.2, 0, 0, 0.3}, "void");
  m.SetRoot(m.AddOperator(NodeType::kDifference, {box, hole}, 0.1, 0.1, 0));
  const PointCloud cloud = Sample(BoxModel(), Vec(-1.5, -1.5, -1.5), Vec(1.5, 1.5, 1.5));
  const SolidVerification v = VerifySolid(m, cloud.points, cloud.normals);
  EXPECT_TRUE(v.bounded);
  EXPECT_FALSE(v.verified);
  EXPECT_EQ(v.components.cavities, 1);
  EXPECT_TRUE(Mentions(v, "unsupported")) << v.message;
  EXPECT_TRUE(Mentions(v, "cavity")) << v.message;
  // its witness lies in the void (within a cell of the sphere's centre region)
  for (const SolidPiece& p : v.components.pieces)
    if (p.cavity) {
      EXPECT_LT((p.witness - Vec(0.2, 0, 0)).norm(), 0.3);
      EXPECT_FALSE(p.supported);
    }
  // The same model with the cavity's points in the cloud verifies.
  const PointCloud both = Sample(m, Vec(-1.5, -1.5, -1.5), Vec(1.5, 1.5, 1.5), 6000);
  const SolidVerification ok = VerifySolid(m, both.points, both.normals);
  EXPECT_TRUE(ok.verified) << ok.message;
  EXPECT_EQ(ok.components.cavities, 1);
}

TEST(SolidVerification, RefusesAnUnsupportedFarPiece) {
  Model m;
  const int box = AddBox(&m, Vec(1, 0.7, 0.5), Vec::Zero(), "p");
  const int ball = m.AddPrimitive(NodeType::kSphere, {3, 0, 0, 0.4}, "ball");
  m.SetRoot(m.AddOperator(NodeType::kUnion, {box, ball}, 0.1, 0.1, 0));
  const PointCloud cloud = Sample(BoxModel(), Vec(-1.5, -1.5, -1.5), Vec(1.5, 1.5, 1.5));
  const SolidVerification v = VerifySolid(m, cloud.points, cloud.normals);
  EXPECT_TRUE(v.bounded);
  EXPECT_FALSE(v.verified);
  EXPECT_EQ(v.components.solids, 2);
  EXPECT_TRUE(Mentions(v, "a solid piece")) << v.message;
}

TEST(SolidVerification, RefusesASwappedInside) {
  // A shell: the box of 1.5 x 1.2 x 1.0 minus the data's box. Bounded and its inner surface
  // lies on the cloud, but its material is where the data's normals point (outside).
  Model m;
  const int outer = AddBox(&m, Vec(1.5, 1.2, 1.0), Vec::Zero(), "outer");
  const int inner = AddBox(&m, Vec(1, 0.7, 0.5), Vec::Zero(), "p");
  m.SetRoot(m.AddOperator(NodeType::kDifference, {outer, inner}, 0.1, 0.1, 0));
  const PointCloud cloud = Sample(BoxModel(), Vec(-1.5, -1.5, -1.5), Vec(1.5, 1.5, 1.5));
  const SolidVerification v = VerifySolid(m, cloud.points, cloud.normals);
  EXPECT_TRUE(v.bounded);
  EXPECT_FALSE(v.verified);
  EXPECT_LT(v.agreement, 0.1);
  EXPECT_TRUE(Mentions(v, "inside/outside disagrees")) << v.message;
  int refused = 0;
  for (const PrimitiveAgreement& p : v.primitives) refused += p.checked && !p.passed;
  EXPECT_EQ(refused, 6);  // each of the data's faces
}

TEST(SolidVerification, ClaimsRoundTripThroughTheMeshGrid) {
  Vec lo, hi;
  double cell;
  DefaultSolidGrid(Vec(0, 0, 0), Vec(10, 5, 2), 100, &lo, &hi, &cell);
  // the box grown by 10% (12 x 6 x 2.4), cell 12 / 100, two cells more on every side
  EXPECT_DOUBLE_EQ(cell, 0.12);
  EXPECT_NEAR(lo.x(), -1 - 0.24, 1e-12);
  EXPECT_NEAR(hi.z(), 2.2 + 0.24, 1e-12);
}

}  // namespace
}  // namespace implicitfit
