// Tree convexity certificate (model/certificates/tree_certificate.h, docs/maths.md LP-4 c) against
// the independent sampling tangent-plane test (model/certificates/tangent_plane_test.h) on whole
// models over a box.
#include "model/certificates/tree_certificate.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "model/certificates/tangent_plane_test.h"
#include "support/random_round_leaf.h"

namespace implicitfit {
namespace {

using Vec = Eigen::Vector3d;

TreeConvexity RootClass(const Model& m) { return CertifyTree(m)[m.root()].convexity; }

TEST(TreeCertificate, LeavesGetTheirClasses) {
  auto single = [](NodeType t, std::vector<double> p) {
    Model m;
    m.AddPrimitive(t, p);
    return RootClass(m);
  };
  EXPECT_EQ(single(NodeType::kPlane, {0, 0, 1, 0}), TreeConvexity::kConvexFunction);
  EXPECT_EQ(single(NodeType::kSphere, {0, 0, 0, 1}), TreeConvexity::kConvexFunction);
  EXPECT_EQ(single(NodeType::kCylinder, {0, 0, 0, 0, 0, 1, 1}), TreeConvexity::kConvexFunction);
  EXPECT_EQ(single(NodeType::kCone, {0, 0, 0, 0, 0, 1, 0.5}), TreeConvexity::kConvexFunction);
  EXPECT_EQ(single(NodeType::kTorus, {0, 0, 0, 0, 0, 1, 1, 0.3}), TreeConvexity::kNotCertified);
  EXPECT_EQ(single(NodeType::kEllipsoid, {0, 0, 0, 1, 0.7, 0.5, 1, 0, 0, 0, 1, 0}),
            TreeConvexity::kConvexSolid);
  // Quadric x^2 + 2 y^2 + z^2 - 1 (A >= 0) and the hyperboloid x^2 + y^2 - z^2 - 1.
  EXPECT_EQ(single(NodeType::kQuadric, {1, 2, 1, 0, 0, 0, 0, 0, 0, -1}),
            TreeConvexity::kConvexSolid);
  EXPECT_EQ(single(NodeType::kQuadric, {1, 1, -1, 0, 0, 0, 0, 0, 0, -1}),
            TreeConvexity::kNotCertified);
}

TEST(TreeCertificate, PatchesAreConvexOnTheirTetrahedronOnly) {
  Model m;
  // f = |x|^2 - 0.25 on the reference tetrahedron: degree 2, b_{e_i+e_j} = x_i . x_j - 0.25.
  const Tetrahedron t;
  std::vector<double> b;
  for (const auto& l : BernsteinMultiIndices(2)) {
    int i = -1, j = -1;
    for (int a = 0; a < 4; ++a)
      for (int c = 0; c < l[a]; ++c) (i < 0 ? i : j) = a;
    b.push_back(t.vertex(i).dot(t.vertex(j)) - 0.25);
  }
  const int patch = m.AddBernsteinPatch(2, t, b);
  const int plane = m.AddPrimitive(NodeType::kPlane, {0, 0, 1, 0.3});
  m.AddOperator(NodeType::kIntersection, {patch, plane}, 0.1, 0.1, 0);
  const std::vector<NodeCertificate> c = CertifyTree(m);
  EXPECT_EQ(c[patch].convexity, TreeConvexity::kConvexFunction);
  EXPECT_EQ(c[m.root()].convexity, TreeConvexity::kConvexFunction);
  EXPECT_EQ(c[m.root()].domain_nodes, std::vector<int>{patch});
  EXPECT_TRUE(c[plane].domain_nodes.empty());
}

Model WitnessTree(BlendSmoothing smoothing) {
  Model m;
  const int a = m.AddPrimitive(NodeType::kPlane, {1, 0, 0, 0});
  const int b = m.AddPrimitive(NodeType::kPlane, {0, 1, 0, 0});
  const int op = m.AddOperator(NodeType::kIntersection, {a, b}, 1.0, 1.0, 3);
  m.mutable_nodes()[op].smoothing = smoothing;
  return m;
}

TEST(TreeCertificate, TheWitnessTreeIsNotCertifiedAndSamplingRefutesIt) {
  const Model lp = WitnessTree(BlendSmoothing::kLiPhillips);
  EXPECT_EQ(RootClass(lp), TreeConvexity::kNotCertified);
  TangentPlaneTestOptions o;
  o.segments = 10000;
  const TangentPlaneTestResult s = TangentPlaneTest(lp, Vec(-3, -3, -0.5), Vec(0.5, 0.5, 0.5), o);
  EXPECT_GT(s.violations, 0) << s.zero_points << " zero points";
  // The same tree with convex smoothing is certified, and sampling agrees.
  const Model cv = WitnessTree(BlendSmoothing::kConvex);
  EXPECT_EQ(RootClass(cv), TreeConvexity::kConvexFunction);
  const TangentPlaneTestResult sc = TangentPlaneTest(cv, Vec(-3, -3, -0.5), Vec(0.5, 0.5, 0.5), o);
  EXPECT_GT(sc.zero_points, 1000);
  EXPECT_EQ(sc.violations, 0) << sc.worst_excursion;
}

TEST(TreeCertificate, ConvexSmoothingIntersectionOfFourPlanesAndASphereIsCertified) {
  Model m;
  std::vector<int> children;
  const Vec normals[4] = {Vec(1, 0, 0.2), Vec(-1, 0.1, 0), Vec(0, 1, -0.1), Vec(0.1, -1, 0)};
  for (const Vec& n : normals)
    children.push_back(m.AddPrimitive(NodeType::kPlane, {n.x(), n.y(), n.z(), 0.6}));
  children.push_back(m.AddPrimitive(NodeType::kSphere, {0, 0, 0, 0.9}));
  const int op = m.AddOperator(NodeType::kIntersection, children, 0.2, 0.2, 3);
  m.mutable_nodes()[op].smoothing = BlendSmoothing::kConvex;
  EXPECT_EQ(RootClass(m), TreeConvexity::kConvexFunction);
  TangentPlaneTestOptions o;
  o.segments = 10000;
  const TangentPlaneTestResult s =
      TangentPlaneTest(m, Vec(-1.2, -1.2, -1.2), Vec(1.2, 1.2, 1.2), o);
  EXPECT_GT(s.zero_points, 1000);
  EXPECT_EQ(s.violations, 0) << s.worst_excursion;
  // Li-Phillips smoothing, a union, a difference: not certified.
  m.mutable_nodes()[op].smoothing = BlendSmoothing::kLiPhillips;
  EXPECT_EQ(RootClass(m), TreeConvexity::kNotCertified);
  m.mutable_nodes()[op].smoothing = BlendSmoothing::kConvex;
  m.mutable_nodes()[op].type = NodeType::kUnion;
  EXPECT_EQ(RootClass(m), TreeConvexity::kNotCertified);
  m.mutable_nodes()[op].type = NodeType::kDifference;
  EXPECT_EQ(RootClass(m), TreeConvexity::kNotCertified);
}

TEST(TreeCertificate, ConvexSolidsNeedASharpIntersection) {
  Model m;
  const int e = m.AddPrimitive(NodeType::kEllipsoid, {0, 0, 0, 1, 0.7, 0.5, 1, 0, 0, 0, 1, 0});
  const int p = m.AddPrimitive(NodeType::kPlane, {0, 0, 1, 0.2});
  const int op = m.AddOperator(NodeType::kIntersection, {e, p}, 0.1, 0.1, 0);
  m.mutable_nodes()[op].smoothing = BlendSmoothing::kConvex;
  EXPECT_EQ(RootClass(m), TreeConvexity::kConvexSolid);
  m.mutable_nodes()[op].order = 3;
  EXPECT_EQ(RootClass(m), TreeConvexity::kNotCertified);
}

// Random trees of convex leaves (planes, spheres, cylinders, cones; ellipsoids and convex
// quadrics under sharp intersections) joined by sharp or convex-smoothing intersections.
int RandomConvexNode(std::mt19937& rng, Model* m, int depth) {
  std::uniform_real_distribution<double> u(-1.0, 1.0), r01(0.0, 1.0);
  auto dir = [&]() { return Vec(u(rng), u(rng), u(rng)).normalized(); };
  if (depth == 0 || r01(rng) < 0.3) {
    const int kind = static_cast<int>(r01(rng) * 6);
    const Vec c = 0.3 * Vec(u(rng), u(rng), u(rng)), a = dir();
    if (kind < 4) return testsupport::AddRandomRoundLeaf(kind, c, a, r01, rng, m);
    switch (kind) {
      case 4: {
        Vec b = dir();
        b = (b - b.dot(a) * a).normalized();
        return m->AddPrimitive(NodeType::kEllipsoid,
                               {c.x(), c.y(), c.z(), 0.6 + 0.5 * r01(rng), 0.6 + 0.5 * r01(rng),
                                0.6 + 0.5 * r01(rng), a.x(), a.y(), a.z(), b.x(), b.y(), b.z()});
      }
      default: {
        // (x - c)^T Q (x - c) - 0.5 with Q = I + v v^T (positive definite).
        const Vec v = 0.8 * dir();
        Eigen::Matrix3d q = Eigen::Matrix3d::Identity() + v * v.transpose();
        const Vec b = -q * c;
        return m->AddPrimitive(NodeType::kQuadric,
                               {q(0, 0), q(1, 1), q(2, 2), q(0, 1), q(0, 2), q(1, 2), b.x(), b.y(),
                                b.z(), c.dot(q * c) - 0.5});
      }
    }
  }
  std::vector<int> children;
  const int n = 2 + static_cast<int>(r01(rng) * 3);
  for (int i = 0; i < n; ++i) children.push_back(RandomConvexNode(rng, m, depth - 1));
  const bool sharp = r01(rng) < 0.4;
  const int op = m->AddOperator(NodeType::kIntersection, children, 0.05 + 0.3 * r01(rng), 0.05,
                                sharp ? 0 : 1 + static_cast<int>(r01(rng) * 4));
  m->mutable_nodes()[op].smoothing = BlendSmoothing::kConvex;
  return op;
}

TEST(TreeCertificate, CertifiedRandomTreesPassTheSamplingTest) {
  std::mt19937 rng(2026);
  int certified = 0, trials = 0;
  while (certified < 12 && trials < 200) {
    ++trials;
    Model m;
    m.SetRoot(RandomConvexNode(rng, &m, 2));
    if (RootClass(m) == TreeConvexity::kNotCertified) continue;
    ++certified;
    TangentPlaneTestOptions o;
    o.segments = 10000;
    o.seed = trials;
    const TangentPlaneTestResult s =
        TangentPlaneTest(m, Vec(-1.5, -1.5, -1.5), Vec(1.5, 1.5, 1.5), o);
    EXPECT_GT(s.zero_points, 100) << "tree " << trials;
    EXPECT_EQ(s.violations, 0) << "tree " << trials << " worst " << s.worst_excursion;
  }
  EXPECT_EQ(certified, 12);
}

}  // namespace
}  // namespace implicitfit

namespace implicitfit {
namespace {

// The rules for box, paraboloid, skeleton offsets and morph, each checked against the sampling
// tangent-plane test over a box around the shape (certified: 0 violations; the concave
// paraboloid and a two-ball skeleton: not certified, and sampling finds a violation).
TEST(TreeCertificate, NewerKindsAgreeWithSampling) {
  TangentPlaneTestOptions o;
  o.segments = 4000;
  const Vec lo(-1.5, -1.5, -1.5), hi(1.5, 1.5, 1.5);
  Model box;
  box.AddPrimitive(NodeType::kBox, {0.1, -0.1, 0.05, 0.9, 0.1, 0.3, 0.2, 0.8, 0.5, 0.3});
  Model bowl, cap;  // kappa > 0 convex, kappa < 0 concave
  bowl.AddPrimitive(NodeType::kParaboloid, {0, 0, 0.2, 0.1, 0, 1, 1.5});
  cap.AddPrimitive(NodeType::kParaboloid, {0, 0, 0.2, 0.1, 0, 1, -1.5});
  Model capsule, two_balls;
  capsule.AddSkeletonOffset(SkeletonKind::kSegments, {-0.5, 0.2, 0.1, 0.5, -0.3, 0.2}, 0.35);
  two_balls.AddSkeletonOffset(SkeletonKind::kPoints, {-0.6, 0, 0, 0.6, 0, 0}, 0.45);
  Model morph;
  const int a = morph.AddPrimitive(NodeType::kSphere, {0, 0, 0, 0.8});
  const int b = morph.AddPrimitive(NodeType::kBox, {0, 0, 0, 1, 0, 0, 0, 0.6, 0.6, 0.6});
  morph.SetRoot(morph.AddComposite(NodeType::kMorph, {a, b}, {0.3}));
  for (const Model* m : {&box, &bowl, &capsule, &morph}) {
    EXPECT_EQ(RootClass(*m), TreeConvexity::kConvexFunction);
    const TangentPlaneTestResult s = TangentPlaneTest(*m, lo, hi, o);
    EXPECT_GT(s.zero_points, 100);
    EXPECT_EQ(s.violations, 0) << s.worst_excursion;
  }
  for (const Model* m : {&cap, &two_balls}) {
    EXPECT_EQ(RootClass(*m), TreeConvexity::kNotCertified);
    EXPECT_GT(TangentPlaneTest(*m, lo, hi, o).violations, 0);
  }
}

}  // namespace
}  // namespace implicitfit
