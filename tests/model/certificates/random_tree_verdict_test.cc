// The file verdict on random trees (model/certificates/convexity_verdict.h), issue 28:
//  - 10^4 random trees of convex-function leaves (plane, sphere, cylinder, cone, box, paraboloid
//    with kappa >= 0, capsule, certified quadric patch) under intersections (sharp or convex
//    smoothing, orders 0..4) and morphs: every one certified, and sampling finds no violation:
//    the midpoint inequality f((a + b) / 2) <= (f(a) + f(b)) / 2 on 16 random pairs per tree
//    (f itself is claimed convex), and on every 100th tree the tangent-plane test of the solid;
//  - 10^4 random trees that join a certified convex patch to a solid disjoint from it (a union,
//    Li-Phillips, convex-smoothing or sharp, possibly under intersections with large convex
//    shapes that contain both): every one refused, and each is shown non-convex independently
//    (a point of each solid inside, the midpoint of the two outside);
//  - 4000 random MIXED trees (convex leaves beside tori, ellipsoids, concave paraboloids,
//    indefinite quadrics, random patches and complements, under unions, differences,
//    intersections with either smoothing, morphs): the verdict is sound against sampling of
//    the solid itself, and of f where f is claimed a convex function. Inside points (f < 0) in
//    [-1.5, 1.5]^3 are paired and 7 points along each segment must be inside too (a convex
//    solid contains its chords); convex-function claims must also pass the midpoint
//    inequality. No convex verdict has a violation; some trees are certified (the test is not
//    vacuous) and many are shown non-convex by the sampling (all of those refused).
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cstdio>
#include <cstdlib>
#include <random>

#include "model/bernstein/bernstein_conversion.h"
#include "model/certificates/convexity_verdict.h"
#include "model/certificates/tangent_plane_test.h"
#include "model/certificates/tree_certificate.h"
#include "model/model.h"
#include "support/random_round_leaf.h"

namespace implicitfit {
namespace {

using Vec = Eigen::Vector3d;

// The random trees' seed: `fallback`, or IMPLICITFIT_TEST_SEED (plus fallback) for a held-out
// set (e.g. IMPLICITFIT_TEST_SEED=1000 model_tests --gtest_filter=RandomTreeVerdict.*).
unsigned TreeSeed(unsigned fallback) {
  const char* env = std::getenv("IMPLICITFIT_TEST_SEED");
  return env ? fallback + static_cast<unsigned>(std::strtoul(env, nullptr, 10)) : fallback;
}

// A tetrahedron that contains the box [-2, 2]^3 (the sampling box lies inside it).
Tetrahedron BigTetrahedron() {
  const double s = 12.0;
  return Tetrahedron(Vec(s, s, s), Vec(s, -s, -s), Vec(-s, s, -s), Vec(-s, -s, s));
}

int RandomConvexLeaf(std::mt19937& rng, Model* m) {
  std::uniform_real_distribution<double> u(-1.0, 1.0), r01(0.0, 1.0);
  auto dir = [&]() { return Vec(u(rng), u(rng), u(rng)).normalized(); };
  const Vec c = 0.3 * Vec(u(rng), u(rng), u(rng)), a = dir();
  const int kind = static_cast<int>(r01(rng) * 8);
  if (kind < 4) return testsupport::AddRandomRoundLeaf(kind, c, a, r01, rng, m);
  switch (kind) {
    case 4: {
      const Eigen::Quaterniond q(r01(rng) + 0.1, u(rng), u(rng), u(rng));
      return m->AddPrimitive(NodeType::kBox,
                             {c.x(), c.y(), c.z(), q.w(), q.x(), q.y(), q.z(), 0.4 + 0.5 * r01(rng),
                              0.4 + 0.5 * r01(rng), 0.4 + 0.5 * r01(rng)});
    }
    case 5:
      return m->AddPrimitive(NodeType::kParaboloid,
                             {c.x(), c.y(), c.z() + 0.5, a.x(), a.y(), a.z(), 2 * r01(rng)});
    case 6:
      return m->AddSkeletonOffset(SkeletonKind::kSegments,
                                  {c.x() - 0.3, c.y(), c.z(), c.x() + 0.3, c.y() + 0.2, c.z()},
                                  0.4 + 0.3 * r01(rng));
    default: {
      // (x - c)^T Q (x - c) - 0.5, Q = I + v v^T: a certified degree-2 patch (A^mu = E^T Q E
      // up to a factor, positive definite) on the big tetrahedron.
      const Vec v = 0.8 * dir();
      CartesianQuadric q;
      q.A = Eigen::Matrix3d::Identity() + v * v.transpose();
      q.b = -q.A * c;
      q.c = c.dot(q.A * c) - 0.5;
      return m->AddBernsteinPatch(2, BigTetrahedron(), QuadricToBernstein(q, BigTetrahedron(), 2));
    }
  }
}

int RandomConvexTree(std::mt19937& rng, Model* m, int depth) {
  std::uniform_real_distribution<double> r01(0.0, 1.0);
  if (depth == 0 || r01(rng) < 0.3) return RandomConvexLeaf(rng, m);
  if (r01(rng) < 0.15) {  // a morph of two convex functions
    const int a = RandomConvexTree(rng, m, depth - 1), b = RandomConvexTree(rng, m, depth - 1);
    return m->AddComposite(NodeType::kMorph, {a, b}, {0.1 + 0.8 * r01(rng)});
  }
  std::vector<int> children;
  const int n = 2 + static_cast<int>(r01(rng) * 3);
  for (int i = 0; i < n; ++i) children.push_back(RandomConvexTree(rng, m, depth - 1));
  const double w = 0.05 + 0.3 * r01(rng);
  const int op =
      m->AddOperator(NodeType::kIntersection, children, w, w, static_cast<int>(r01(rng) * 5));
  m->mutable_nodes()[op].smoothing = BlendSmoothing::kConvex;
  return op;
}

// A leaf that may or may not be convex.
int RandomMixedLeaf(std::mt19937& rng, Model* m) {
  std::uniform_real_distribution<double> u(-1.0, 1.0), r01(0.0, 1.0);
  auto dir = [&]() { return Vec(u(rng), u(rng), u(rng)).normalized(); };
  const Vec c = 0.4 * Vec(u(rng), u(rng), u(rng)), a = dir(), e = dir();
  switch (static_cast<int>(r01(rng) * 7)) {
    case 0:
      return m->AddPrimitive(NodeType::kTorus, {c.x(), c.y(), c.z(), a.x(), a.y(), a.z(),
                                                0.5 + 0.4 * r01(rng), 0.15 + 0.25 * r01(rng)});
    case 1:
      return m->AddPrimitive(NodeType::kEllipsoid,
                             {c.x(), c.y(), c.z(), 0.3 + 0.8 * r01(rng), 0.3 + 0.8 * r01(rng),
                              0.3 + 0.8 * r01(rng), a.x(), a.y(), a.z(), e.x(), e.y(), e.z()});
    case 2:  // a concave cap
      return m->AddPrimitive(NodeType::kParaboloid,
                             {c.x(), c.y(), c.z(), a.x(), a.y(), a.z(), -2 * r01(rng)});
    case 3: {  // a random quadric (mostly indefinite)
      std::vector<double> q(10);
      for (double& v : q) v = u(rng);
      q[9] = -0.3 * r01(rng);
      return m->AddPrimitive(NodeType::kQuadric, q);
    }
    case 4: {  // a random degree-2 or -3 patch on the big tetrahedron
      const int k = 2 + static_cast<int>(r01(rng) * 2);
      std::vector<double> b(NumBernsteinControlPoints(k));
      for (double& v : b) v = u(rng);
      return m->AddBernsteinPatch(k, BigTetrahedron(), b);
    }
    case 5:
      return m->AddComposite(NodeType::kComplement, {RandomConvexLeaf(rng, m)}, {});
    default:
      return RandomConvexLeaf(rng, m);
  }
}

int RandomMixedTree(std::mt19937& rng, Model* m, int depth) {
  std::uniform_real_distribution<double> r01(0.0, 1.0);
  if (depth == 0 || r01(rng) < 0.3)
    return r01(rng) < 0.5 ? RandomConvexLeaf(rng, m) : RandomMixedLeaf(rng, m);
  const double pick = r01(rng);
  if (pick < 0.1) {
    const int a = RandomMixedTree(rng, m, depth - 1), b = RandomMixedTree(rng, m, depth - 1);
    return m->AddComposite(NodeType::kMorph, {a, b}, {0.1 + 0.8 * r01(rng)});
  }
  const NodeType type = pick < 0.3    ? NodeType::kUnion
                        : pick < 0.45 ? NodeType::kDifference
                                      : NodeType::kIntersection;
  std::vector<int> children;
  const int n = type == NodeType::kDifference ? 2 : 2 + static_cast<int>(r01(rng) * 2);
  for (int i = 0; i < n; ++i) children.push_back(RandomMixedTree(rng, m, depth - 1));
  const double w = 0.05 + 0.3 * r01(rng);
  const int op = m->AddOperator(type, children, w, w, static_cast<int>(r01(rng) * 5));
  if (r01(rng) < 0.5) m->mutable_nodes()[op].smoothing = BlendSmoothing::kConvex;
  return op;
}

TEST(RandomTreeVerdict, MixedTreesNeverCalledConvexWhenSamplingShowsOtherwise) {
  std::mt19937 rng(TreeSeed(30));
  std::uniform_real_distribution<double> u(-1.5, 1.5);
  int certified = 0, functions = 0, shown_non_convex = 0, chord_violations = 0,
      midpoint_violations = 0, checked_chords = 0;
  for (int trial = 0; trial < 4000; ++trial) {
    Model m;
    m.SetRoot(RandomMixedTree(rng, &m, 2));
    const ConvexityVerdict v = JudgeConvexity(m);
    const bool function_claim =
        v.convex && CertifyTree(m)[m.root()].convexity == TreeConvexity::kConvexFunction;
    std::vector<Vec> inside;
    for (int i = 0; i < 96 && inside.size() < 16; ++i) {
      const Vec x(u(rng), u(rng), u(rng));
      if (m.Value(x) < 0) inside.push_back(x);
    }
    bool violated = false;
    for (size_t i = 0; i + 1 < inside.size(); ++i)
      for (size_t j = i + 1; j < inside.size(); j += 3) {
        ++checked_chords;
        for (int s = 1; s < 8; ++s)
          if (m.Value(inside[i] + (s / 8.0) * (inside[j] - inside[i])) > 1e-9) violated = true;
      }
    int midpoint_bad = 0;
    if (function_claim)
      for (int pair = 0; pair < 16; ++pair) {
        const Vec a(u(rng), u(rng), u(rng)), b(u(rng), u(rng), u(rng));
        const double fa = m.Value(a), fb = m.Value(b), fm = m.Value(0.5 * (a + b));
        if (fm > 0.5 * (fa + fb) + 1e-12 * (1 + std::abs(fa) + std::abs(fb))) ++midpoint_bad;
      }
    shown_non_convex += violated;
    if (v.convex) {
      ++certified;
      functions += function_claim;
      chord_violations += violated;
      midpoint_violations += midpoint_bad;
      EXPECT_FALSE(violated) << "tree " << trial << " called convex, a chord leaves its solid";
      EXPECT_EQ(midpoint_bad, 0) << "tree " << trial << " called a convex function";
    }
  }
  std::printf(
      "  mixed trees: %d of 4000 certified (%d convex functions), %d shown non-convex by "
      "%d chords, violations among the certified: chords %d, midpoints %d\n",
      certified, functions, shown_non_convex, checked_chords, chord_violations,
      midpoint_violations);
  EXPECT_GT(certified, 100);
  EXPECT_GT(shown_non_convex, 500);
}

TEST(RandomTreeVerdict, TenThousandConvexTreesCertifiedWithoutSamplingViolations) {
  std::mt19937 rng(TreeSeed(28));
  std::uniform_real_distribution<double> u(-1.5, 1.5);
  int midpoint_violations = 0, tangent_violations = 0, tangent_zero_points = 0, refused = 0;
  for (int trial = 0; trial < 10000; ++trial) {
    Model m;
    m.SetRoot(RandomConvexTree(rng, &m, 2));
    const ConvexityVerdict v = JudgeConvexity(m);
    if (!v.convex) {
      ++refused;
      ADD_FAILURE() << "tree " << trial << " refused: " << v.reason;
      continue;
    }
    for (int pair = 0; pair < 16; ++pair) {
      const Vec a(u(rng), u(rng), u(rng)), b(u(rng), u(rng), u(rng));
      const double fa = m.Value(a), fb = m.Value(b), fm = m.Value(0.5 * (a + b));
      if (fm > 0.5 * (fa + fb) + 1e-12 * (1 + std::abs(fa) + std::abs(fb))) ++midpoint_violations;
    }
    if (trial % 100 == 0) {
      TangentPlaneTestOptions o;
      o.segments = 400;
      o.seed = trial;
      const TangentPlaneTestResult s =
          TangentPlaneTest(m, Vec(-1.5, -1.5, -1.5), Vec(1.5, 1.5, 1.5), o);
      tangent_violations += s.violations;
      tangent_zero_points += s.zero_points;
    }
  }
  EXPECT_EQ(refused, 0);
  EXPECT_EQ(midpoint_violations, 0);
  EXPECT_EQ(tangent_violations, 0);
  EXPECT_GT(tangent_zero_points, 5000);  // the sampling test had something to test
}

TEST(RandomTreeVerdict, EveryTreeJoiningACertifiedPatchToADisjointSolidIsRefused) {
  std::mt19937 rng(TreeSeed(29));
  std::uniform_real_distribution<double> u(-1.0, 1.0), r01(0.0, 1.0);
  for (int trial = 0; trial < 10000; ++trial) {
    Model m;
    // The patch: a certified ball of radius 0.5 about c on a tetrahedron around it.
    const Vec c = 0.2 * Vec(u(rng), u(rng), u(rng));
    CartesianQuadric q;
    q.A = Eigen::Matrix3d::Identity();
    q.b = -c;
    q.c = c.squaredNorm() - 0.25;
    const Tetrahedron tet(c + Vec(2, 2, 2), c + Vec(2, -2, -2), c + Vec(-2, 2, -2),
                          c + Vec(-2, -2, 2));
    const int patch = m.AddBernsteinPatch(2, tet, QuadricToBernstein(q, tet, 2));
    // The disjoint solid, 4..8 away along a random direction: a sphere, a box or a patch.
    const Vec d = Vec(u(rng), u(rng), u(rng)).normalized(), far = c + (4 + 4 * r01(rng)) * d;
    int other;
    const double kind = r01(rng);
    if (kind < 0.4) {
      other = m.AddPrimitive(NodeType::kSphere, {far.x(), far.y(), far.z(), 0.3 + 0.5 * r01(rng)});
    } else if (kind < 0.7) {
      other =
          m.AddPrimitive(NodeType::kBox, {far.x(), far.y(), far.z(), 1, 0, 0, 0, 0.4, 0.3, 0.5});
    } else {
      CartesianQuadric p = q;
      p.b = -far;
      p.c = far.squaredNorm() - 0.25;
      const Tetrahedron t2(far + Vec(2, 2, 2), far + Vec(2, -2, -2), far + Vec(-2, 2, -2),
                           far + Vec(-2, -2, 2));
      other = m.AddBernsteinPatch(2, t2, QuadricToBernstein(p, t2, 2));
    }
    // The join: a union with any smoothing and order.
    const double w = 0.05 + 0.3 * r01(rng);
    const int order = static_cast<int>(r01(rng) * 5);
    int root = m.AddOperator(NodeType::kUnion, {patch, other}, w, 0.5 * w, order);
    if (r01(rng) < 0.4) m.mutable_nodes()[root].smoothing = BlendSmoothing::kConvex;
    // Under up to two sharp or convex-smoothing intersections with a large ball around both.
    const int wraps = static_cast<int>(r01(rng) * 3);
    for (int k = 0; k < wraps; ++k) {
      const Vec mid = 0.5 * (c + far);
      const int big = m.AddPrimitive(NodeType::kSphere, {mid.x(), mid.y(), mid.z(), 20.0});
      root = m.AddOperator(NodeType::kIntersection, {root, big}, 0.1, 0.1, k % 2 ? 0 : 3);
      m.mutable_nodes()[root].smoothing = BlendSmoothing::kConvex;
    }
    m.SetRoot(root);
    const ConvexityVerdict v = JudgeConvexity(m);
    EXPECT_FALSE(v.convex) << "tree " << trial;
    // Independently: both centres inside, the midpoint outside: not a convex solid.
    ASSERT_LT(m.Value(c), 0.0) << trial;
    ASSERT_LT(m.Value(far), 0.0) << trial;
    ASSERT_GT(m.Value(0.5 * (c + far)), 0.0) << trial;
  }
}

}  // namespace
}  // namespace implicitfit
