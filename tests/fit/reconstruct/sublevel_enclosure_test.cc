// The structural bound of fit/reconstruct/sublevel_enclosure.h with the exact polyhedra of
// fit/reconstruct/polytope_box.h, on hand-built trees whose extent is known in closed form:
// unbounded ones (a plane, an infinite cylinder, a cylinder with one cap, a union with an
// infinite tube, a complement) must be refused whatever the sampling, bounded ones must give a
// box that holds the solid (closed form) and is not much larger (the octagonal prism about a
// cylinder reaches at most r / cos(22.5 deg) radially), and, independently of the proof, f must
// be > 0 at random points outside the box.
#include "fit/reconstruct/sublevel_enclosure.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "fit/reconstruct/polytope_box.h"

namespace implicitfit {
namespace {

using Vec = Eigen::Vector3d;

const double kOctagon = 1.0 / std::cos(M_PI / 8);  // circumradius / inradius of an octagon

struct Bound {
  bool bounded = false;
  Vec lo, hi;
  Vec witness;  // of the first unbounded piece
};

// The proof with the limit box [-1e4, 1e4]^3; the witness: the exit with the lowest f.
Bound Prove(const Model& m) {
  const SublevelEnclosure e = EncloseSublevel(m);
  Bound b;
  b.bounded = true;
  b.lo = Vec::Constant(1e300);
  b.hi = Vec::Constant(-1e300);
  for (const EnclosurePiece& piece : e.pieces) {
    const PolytopeBox box = BoundPolytope(piece.faces, Vec::Constant(-1e4), Vec::Constant(1e4));
    if (box.extent == PolytopeExtent::kEmpty) continue;
    if (box.extent != PolytopeExtent::kBounded) {
      EXPECT_EQ(box.extent, PolytopeExtent::kBeyondLimit) << piece.label;
      for (const PolytopeBox::Exit& exit : box.exits) {
        EXPECT_TRUE(exit.infinite) << piece.label;  // the trees here are unbounded or small
        for (const Vec& w : exit.witnesses) {
          if (b.bounded || m.Value(w) < m.Value(b.witness)) b.witness = w;
          b.bounded = false;
        }
      }
      continue;
    }
    b.lo = b.lo.cwiseMin(box.lo);
    b.hi = b.hi.cwiseMax(box.hi);
  }
  return b;
}

// f > 0 at random points of the shell between the box grown by 1% and a box 20 times larger.
void ExpectPositiveOutside(const Model& m, const Bound& b) {
  std::mt19937 rng(7);
  const Vec centre = 0.5 * (b.lo + b.hi), half = 0.5 * (b.hi - b.lo) * 1.01;
  std::uniform_real_distribution<double> u(-20, 20);
  int tested = 0;
  while (tested < 20000) {
    const Vec x = centre + Vec(u(rng), u(rng), u(rng)).cwiseProduct(half);
    if (((x - centre).cwiseAbs().array() <= half.array()).all()) continue;
    ++tested;
    ASSERT_GT(m.Value(x), 0) << x.transpose();
  }
}

Model Plane(const Vec& n, double d) {
  Model m;
  m.SetRoot(m.AddPrimitive(NodeType::kPlane, {n.x(), n.y(), n.z(), d}, "plane"));
  return m;
}

// A cylinder of radius r about (0, 0, z) with caps z <= top and -z <= -bottom, optionally
// tilted: the axis a (unit), caps perpendicular to it.
Model CappedCylinder(double r, double bottom, double top, const Vec& a, int order = 0) {
  Model m;
  const int c = m.AddPrimitive(NodeType::kCylinder, {0, 0, 0, a.x(), a.y(), a.z(), r}, "side");
  const int t = m.AddPrimitive(NodeType::kPlane, {a.x(), a.y(), a.z(), top}, "top");
  const int b = m.AddPrimitive(NodeType::kPlane, {-a.x(), -a.y(), -a.z(), -bottom}, "bottom");
  m.SetRoot(m.AddOperator(NodeType::kIntersection, {c, t, b}, 0.2, 0.1, order));
  return m;
}

TEST(SublevelEnclosure, APlaneIsAHalfSpaceNotBounded) {
  const Model m = Plane(Vec(0, 0, 1), 0.5);
  const Bound b = Prove(m);
  EXPECT_FALSE(b.bounded);
  EXPECT_LE(m.Value(b.witness), 0);  // the far point is inside the half-space
}

TEST(SublevelEnclosure, AnInfiniteCylinderIsNotBounded) {
  Model m;
  m.SetRoot(m.AddPrimitive(NodeType::kCylinder, {0, 0, 0, 0, 0, 1, 6}, "shank"));
  const Bound b = Prove(m);
  EXPECT_FALSE(b.bounded);
  EXPECT_LE(m.Value(b.witness), 0);
  EXPECT_GE(std::abs(b.witness.z()), 1e4 - 1e-6);  // far along the axis, where the tube goes
}

TEST(SublevelEnclosure, ACylinderWithOneCapIsNotBounded) {
  Model m;
  const int c = m.AddPrimitive(NodeType::kCylinder, {0, 0, 0, 0, 0, 1, 6}, "shank");
  const int cap = m.AddPrimitive(NodeType::kPlane, {0, 0, -1, 40}, "bottom");  // z >= -40
  m.SetRoot(m.AddOperator(NodeType::kIntersection, {c, cap}, 0.1, 0.1, 0));
  const Bound b = Prove(m);
  EXPECT_FALSE(b.bounded);
  EXPECT_GT(b.witness.z(), 1e4 - 1e-6);  // up the open end
  EXPECT_LE(m.Value(b.witness), 0);
}

TEST(SublevelEnclosure, ATubeClosedOnlyByRoundingIsRefusedAtTheLimit) {
  // Reconstructed PC34's flange cylinder (axis 8e-8 off z) above a nearly horizontal separator
  // (z >= -0.41): open upwards. The prism's rounded faces close it ~1e17 away in exact
  // arithmetic; inside the limit box it must count as leaving it, with f < 0 at the witness.
  Model m;
  const int c = m.AddPrimitive(NodeType::kCylinder,
                               {-2.29e-8, -3.22e-8, 0.5458, -3.712e-08, -7.098e-08, -1, 10.5}, "p3");
  const int cut = m.AddPrimitive(NodeType::kPlane, {-0.00044008, 0.00313485, -0.999995, 0.40994},
                                 "separator0");
  m.SetRoot(m.AddOperator(NodeType::kIntersection, {c, cut}, 0.1, 0.1, 0));
  const SublevelEnclosure e = EncloseSublevel(m);
  ASSERT_EQ(e.pieces.size(), 1u);
  const PolytopeBox box = BoundPolytope(e.pieces[0].faces, Vec::Constant(-100), Vec::Constant(100));
  EXPECT_EQ(box.extent, PolytopeExtent::kBeyondLimit);
  const PolytopeBox::Exit* up = nullptr;
  for (const PolytopeBox::Exit& exit : box.exits)
    if (exit.direction.z() > 0) up = &exit;
  ASSERT_NE(up, nullptr);
  ASSERT_FALSE(up->witnesses.empty());
  EXPECT_GE(up->witnesses[0].z(), 100);
  EXPECT_NEAR(m.Value(up->witnesses[0]), -10.5, 0.1);  // on the tube's axis
}

TEST(SublevelEnclosure, ACappedCylinderIsBoundedByItsPrism) {
  for (const int order : {0, 3}) {
    const Model m = CappedCylinder(6, -40, 0, Vec::UnitZ(), order);
    const Bound b = Prove(m);
    ASSERT_TRUE(b.bounded);
    for (int a = 0; a < 2; ++a) {
      EXPECT_LE(b.lo[a], -6);
      EXPECT_GE(b.lo[a], -6 * kOctagon - 1e-6);
      EXPECT_GE(b.hi[a], 6);
      EXPECT_LE(b.hi[a], 6 * kOctagon + 1e-6);
    }
    EXPECT_NEAR(b.lo.z(), -40, 1e-6);
    EXPECT_NEAR(b.hi.z(), 0, 1e-6);
    ExpectPositiveOutside(m, b);
  }
}

TEST(SublevelEnclosure, ATiltedCappedCylinderHoldsItsEndDisks) {
  const Vec a = Vec(1, 2, 2) / 3.0;
  const Model m = CappedCylinder(1, -2, 3, a, 3);
  const Bound b = Prove(m);
  ASSERT_TRUE(b.bounded);
  // The solid's extent along axis x_i: the end centres +- r sqrt(1 - a_i^2).
  for (int i = 0; i < 3; ++i) {
    const double rim = std::sqrt(1 - a[i] * a[i]);
    EXPECT_LE(b.lo[i], std::min(-2 * a[i], 3 * a[i]) - rim + 1e-9);
    EXPECT_GE(b.hi[i], std::max(-2 * a[i], 3 * a[i]) + rim - 1e-9);
  }
  ExpectPositiveOutside(m, b);
}

TEST(SublevelEnclosure, AUnionWithAnInfiniteTubeIsNotBounded) {
  // PC34's failure: a capped shank and, in another term, the socket's tube left open.
  Model m = CappedCylinder(6, -40, 0, Vec::UnitZ());
  const int tube = m.AddPrimitive(NodeType::kCylinder, {0, 0, 0, 0, 0, 1, 3}, "tube");
  const int floor = m.AddPrimitive(NodeType::kPlane, {0, 0, -1, 0}, "floor");  // z >= 0
  const int term = m.AddOperator(NodeType::kIntersection, {tube, floor}, 0.1, 0.1, 0);
  m.SetRoot(m.AddOperator(NodeType::kUnion, {m.root(), term}, 0.5, 0.3, 3));
  const Bound b = Prove(m);
  EXPECT_FALSE(b.bounded);
  EXPECT_LE(m.Value(b.witness), 0);
  EXPECT_GT(b.witness.z(), 1e3);
}

TEST(SublevelEnclosure, ADifferenceIsBoundedByItsMinuendOrByPlaneSubtrahends) {
  // cylinder minus the half-space z >= 1 minus the half-space z <= -1: a capped cylinder.
  Model m;
  const int c = m.AddPrimitive(NodeType::kCylinder, {0, 0, 0, 0, 0, 1, 1}, "side");
  const int above = m.AddPrimitive(NodeType::kPlane, {0, 0, -1, -1}, "above");  // z >= 1
  const int below = m.AddPrimitive(NodeType::kPlane, {0, 0, 1, -1}, "below");   // z <= -1
  m.SetRoot(m.AddOperator(NodeType::kDifference, {c, above, below}, 0.2, 0.1, 3));
  Bound b = Prove(m);
  ASSERT_TRUE(b.bounded);
  EXPECT_LE(b.lo.z(), -1);
  EXPECT_GE(b.hi.z(), 1);
  EXPECT_LE(b.hi.z(), 1 + 1e-6);  // a smooth difference is >= the sharp one: no reach needed
  ExpectPositiveOutside(m, b);
  // A sphere minus an infinite cylinder (a bored ball) is bounded by the sphere.
  Model bored;
  const int s = bored.AddPrimitive(NodeType::kSphere, {1, 2, 3, 2}, "ball");
  const int bore = bored.AddPrimitive(NodeType::kCylinder, {1, 2, 3, 0, 0, 1, 0.5}, "bore");
  bored.SetRoot(bored.AddOperator(NodeType::kDifference, {s, bore}, 0.2, 0.1, 3));
  b = Prove(bored);
  ASSERT_TRUE(b.bounded);
  EXPECT_NEAR(b.lo.x(), -1, 1e-6);
  EXPECT_NEAR(b.hi.z(), 5, 1e-6);
  ExpectPositiveOutside(bored, b);
}

TEST(SublevelEnclosure, ASmoothUnionReachesBeyondItsChildrenByAQuarterDelta) {
  // Two spheres touching at the origin: the smooth union fills the neck up to delta / 4 beyond
  // min(a, b); the enclosure must hold it (checked by sampling outside its box).
  Model m;
  const int a = m.AddPrimitive(NodeType::kSphere, {-1, 0, 0, 1}, "a");
  const int b2 = m.AddPrimitive(NodeType::kSphere, {1, 0, 0, 1}, "b");
  m.SetRoot(m.AddOperator(NodeType::kUnion, {a, b2}, 0.8, 0.8, 3));
  const Bound b = Prove(m);
  ASSERT_TRUE(b.bounded);
  EXPECT_NEAR(b.hi.x(), 2 + 0.8 / 4, 1e-6);
  ExpectPositiveOutside(m, b);
}

TEST(SublevelEnclosure, ComplementsAndUnknownKindsAreNotProven) {
  Model outside;
  const int s = outside.AddPrimitive(NodeType::kSphere, {0, 0, 0, 1});
  outside.SetRoot(outside.AddComposite(NodeType::kComplement, {s}, {}));
  EXPECT_FALSE(Prove(outside).bounded);
  // the complement of the complement is the ball again
  Model twice = outside;
  twice.SetRoot(twice.AddComposite(NodeType::kComplement, {twice.root()}, {}));
  EXPECT_TRUE(Prove(twice).bounded);
  // a quadric (here an ellipsoid's equation) has no structural bound: not proven
  Model q;
  q.SetRoot(q.AddPrimitive(NodeType::kQuadric, {1, 2, 3, 0, 0, 0, 0, 0, 0, -1}));
  const SublevelEnclosure e = EncloseSublevel(q);
  ASSERT_EQ(e.pieces.size(), 1u);
  EXPECT_TRUE(e.pieces[0].faces.empty());
  EXPECT_NE(e.pieces[0].unbounded_reason.find("quadric"), std::string::npos);
}

TEST(SublevelEnclosure, TorusConeAndBoxBounds) {
  Model torus;
  torus.SetRoot(torus.AddPrimitive(NodeType::kTorus, {0, 0, 1, 0, 0, 1, 3, 1}));
  Bound b = Prove(torus);
  ASSERT_TRUE(b.bounded);
  EXPECT_NEAR(b.lo.z(), 0, 1e-6);
  EXPECT_NEAR(b.hi.z(), 2, 1e-6);
  EXPECT_GE(b.hi.x(), 4);
  EXPECT_LE(b.hi.x(), 4 * kOctagon + 1e-6);
  ExpectPositiveOutside(torus, b);
  // A cone (apex 0, axis z, 30 degrees) cut by z <= 2: radius 2 tan(30 deg) at the top.
  Model cone;
  const int k = cone.AddPrimitive(NodeType::kCone, {0, 0, 0, 0, 0, 1, M_PI / 6});
  const int cap = cone.AddPrimitive(NodeType::kPlane, {0, 0, 1, 2});
  cone.SetRoot(cone.AddOperator(NodeType::kIntersection, {k, cap}, 0.1, 0.1, 0));
  b = Prove(cone);
  ASSERT_TRUE(b.bounded);
  const double top = 2 * std::tan(M_PI / 6);
  EXPECT_NEAR(b.lo.z(), 0, 1e-6);
  EXPECT_GE(b.hi.x(), top);
  EXPECT_LE(b.hi.x(), top * kOctagon + 1e-6);
  ExpectPositiveOutside(cone, b);
  // A rotated box: its 6 faces.
  Model box;
  box.SetRoot(box.AddPrimitive(NodeType::kBox, {1, 1, 1, std::cos(0.3), 0, 0, std::sin(0.3),
                                                 2, 1, 0.5}));
  b = Prove(box);
  ASSERT_TRUE(b.bounded);
  ExpectPositiveOutside(box, b);
  // Disjoint half-spaces: an empty intersection is empty, not unbounded.
  Model none;
  const int p = none.AddPrimitive(NodeType::kPlane, {0, 0, 1, -1});   // z <= -1
  const int q2 = none.AddPrimitive(NodeType::kPlane, {0, 0, -1, -1}); // z >= 1
  none.SetRoot(none.AddOperator(NodeType::kIntersection, {p, q2}, 0.1, 0.1, 0));
  const SublevelEnclosure e = EncloseSublevel(none);
  ASSERT_EQ(e.pieces.size(), 1u);
  EXPECT_EQ(BoundPolytope(e.pieces[0].faces, Vec::Constant(-10), Vec::Constant(10)).extent,
            PolytopeExtent::kEmpty);
}

}  // namespace
}  // namespace implicitfit
