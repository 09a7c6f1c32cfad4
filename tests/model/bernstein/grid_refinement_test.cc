// Adaptive Bernstein meshes (model/bernstein/grid_refinement.h, bernstein_mesh.h) and their
// continuity across levels (model/bernstein/bernstein_mesh_continuity.h), checked against
// independent evaluations: oracle barycentric coordinates, the polynomials of the tetrahedra on
// both sides of every face evaluated at points of the face (values and finite-difference-free
// gradients), and the nesting of the spaces.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <random>

#include "model/bernstein/bernstein_conversion.h"
#include "model/bernstein/bernstein_mesh_continuity.h"
#include "model/file/model_json.h"
#include "oracle/bernstein_oracle.h"
#include "support/grid_locate_check.h"

namespace implicitfit {
namespace {

using Vec = Eigen::Vector3d;

BernsteinGrid Base(int nx, int ny, int nz) {
  BernsteinGrid g;
  g.origin = Vec(-0.3, 0.1, 0.2);
  g.cell = 0.5;
  g.cells = {nx, ny, nz};
  return g;
}

// A 2 x 1 x 1 grid with base cube 0 split and its child at octant 7 split again (levels 0-2,
// hanging faces of both level steps and a 2:1 violation-free layout).
const char kRefinedSplits[] =
    "1"
    "0000000"
    "100000000"
    "0";
BernsteinGrid Refined() {
  BernsteinGrid g = Base(2, 1, 1);
  g.refinement = RefinementFromSplits(g.cells, kRefinedSplits);
  return g;
}

std::array<Vec, 4> Corners(const BernsteinGrid& g, long long t) {
  const Tetrahedron tet = g.TetrahedronOf(t);
  return {tet.vertex(0), tet.vertex(1), tet.vertex(2), tet.vertex(3)};
}

TEST(GridRefinement, SplitFlagsRoundTripAndBadFlagsAreRefused) {
  const std::array<int, 3> cells = {2, 1, 1};
  const std::string flags = "1000000001";  // wrong: the second cube's '1' has no children
  EXPECT_THROW(RefinementFromSplits(cells, flags), std::invalid_argument);
  EXPECT_THROW(RefinementFromSplits(cells, "0"), std::invalid_argument);    // too few
  EXPECT_THROW(RefinementFromSplits(cells, "000"), std::invalid_argument);  // too many
  EXPECT_THROW(RefinementFromSplits(cells, "0x"), std::invalid_argument);   // not a flag
  const GridRefinement r = RefinementFromSplits(cells, "1000000000");
  EXPECT_EQ(r.leaves.size(), 9u);
  EXPECT_EQ(r.max_level, 1);
  EXPECT_EQ(SplitsOf(r), "1000000000");
  // Children in octant order: octant 5 = upper x, lower y, upper z of base cube 0.
  EXPECT_EQ(r.leaves[5], (std::array<int, 4>{1, 1, 0, 1}));
  EXPECT_EQ(r.leaves[8], (std::array<int, 4>{0, 1, 0, 0}));
  std::vector<int> parent;
  const GridRefinement s = SplitLeaves(
      cells, r, std::vector<bool>{false, false, false, false, false, false, false, false, true},
      &parent);
  EXPECT_EQ(SplitsOf(s),
            "1000000001"
            "00000000");
  EXPECT_EQ(parent.size(), 16u);
  EXPECT_EQ(parent[15], 8);
  EXPECT_EQ(parent[3], 3);
}

TEST(GridRefinement, BalanceSplitsTheCoarserNeighbours) {
  const std::array<int, 3> cells = {2, 1, 1};
  const GridRefinement r = RefinementFromSplits(cells, "1000000000");
  // Splitting child 1 (upper x of cube 0, touching base cube 1 at level 0) forces cube 1.
  std::vector<bool> split(r.leaves.size(), false);
  split[1] = true;
  const std::vector<bool> balanced = BalanceSplits(cells, r, split);
  EXPECT_TRUE(balanced[8]);
  EXPECT_EQ(std::count(balanced.begin(), balanced.end(), true), 2);
  // Child 0 (lower x) does not touch cube 1: nothing else.
  split.assign(r.leaves.size(), false);
  split[0] = true;
  EXPECT_EQ(BalanceSplits(cells, r, split), split);
}

TEST(GridRefinement, LeavesTileTheBoxAndLocateFindsTheHoldingTetrahedron) {
  const BernsteinGrid g = Refined();
  ASSERT_EQ(g.NumLeaves(), 7 + 8 + 1);
  double volume = 0;
  for (long long t = 0; t < g.NumTetrahedra(); ++t) {
    const auto c = Corners(g, t);
    Eigen::Matrix3d e;
    for (int i = 0; i < 3; ++i) e.col(i) = c[i] - c[3];
    volume += std::abs(e.determinant()) / 6;
  }
  const Vec ext = g.BoxMax() - g.BoxMin();
  EXPECT_NEAR(volume, ext.prod(), 1e-12);
  testsupport::ExpectLocateMatchesOracle(
      g, [&](long long t) { return Corners(g, t); }, 3000, 5);
}

TEST(GridRefinement, ReexpressionGivesTheSamePolynomialOnAnotherTetrahedron) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const Tetrahedron t(Vec(0, 0, 0), Vec(1, 0, 0), Vec(0, 1, 0), Vec(0, 0, 1));
  const Tetrahedron s(Vec(0.3, -0.2, 0.1), Vec(1.4, 0.2, 0), Vec(0, 0.9, 0.5), Vec(0.2, 0.1, 1.3));
  for (int k = 1; k <= 5; ++k) {
    const long long n = NumBernsteinControlPoints(k);
    Eigen::VectorXd b(n);
    for (long long i = 0; i < n; ++i) b[i] = u(rng);
    Eigen::Matrix4d a;
    for (int i = 0; i < 4; ++i) {
      double tau[4];
      t.Barycentric(s.vertex(i).data(), tau);
      a.row(i) << tau[0], tau[1], tau[2], tau[3];
    }
    const Eigen::VectorXd bs = ReexpressionMatrix(k, a) * b;
    for (int m = 0; m < 20; ++m) {
      const Vec x(u(rng), u(rng), u(rng));
      EXPECT_NEAR(BernsteinPatch::Evaluate(k, s, bs.data(), x.data()),
                  BernsteinPatch::Evaluate(k, t, b.data(), x.data()), 1e-10)
          << k;
    }
  }
}

// For every face of every tetrahedron: a point of the face, and the tetrahedron across it.
struct FacePoint {
  long long inner, outer;
  Vec x;
};
std::vector<FacePoint> InteriorFacePoints(const BernsteinGrid& g, std::mt19937* rng) {
  std::uniform_real_distribution<double> u(0.05, 1.0);
  std::vector<FacePoint> out;
  const Vec lo = g.BoxMin(), hi = g.BoxMax();
  for (long long t = 0; t < g.NumTetrahedra(); ++t) {
    const auto c = Corners(g, t);
    for (int q = 0; q < 4; ++q) {
      double w[3] = {u(*rng), u(*rng), u(*rng)};
      const double sum = w[0] + w[1] + w[2];
      Vec x = Vec::Zero();
      int m = 0;
      for (int i = 0; i < 4; ++i)
        if (i != q) x += w[m++] / sum * c[i];
      const Vec across = x + 1e-7 * (x - c[q]);
      if (((across - lo).array() <= 0).any() || ((across - hi).array() >= 0).any()) continue;
      double tau[4];
      out.push_back({t, g.Locate(across.data(), tau), x});
    }
  }
  return out;
}

double Value(const BernsteinGrid& g, int k, const Eigen::VectorXd& b, long long t, const Vec& x,
             Vec* gradient) {
  return BernsteinPatch::Derivatives(
      k, g.TetrahedronOf(t), b.data() + t * NumBernsteinControlPoints(k), x.data(), gradient);
}

TEST(GridRefinement, C0ParametrizationIsContinuousAcrossHangingFaces) {
  const BernsteinGrid g = Refined();
  std::mt19937 rng(11);
  std::normal_distribution<double> z(0.0, 1.0);
  for (int k : {1, 2, 3}) {
    const C0Parametrization c0 = BernsteinC0Parametrization(g, k);
    Eigen::VectorXd w(c0.unknowns);
    for (long long i = 0; i < w.size(); ++i) w[i] = z(rng);
    const Eigen::VectorXd b = c0.P * w;
    double worst = 0;
    int hanging = 0;
    for (const FacePoint& f : InteriorFacePoints(g, &rng)) {
      Vec g1, g2;
      worst = std::max(
          worst, std::abs(Value(g, k, b, f.inner, f.x, &g1) - Value(g, k, b, f.outer, f.x, &g2)));
      hanging += g.LevelOf(f.inner) != g.LevelOf(f.outer);
    }
    EXPECT_GT(hanging, 20);
    EXPECT_LT(worst, 1e-12) << "k = " << k;
    EXPECT_LE(ContinuityDefect(g, k, 0, b.data()), 1e-13);
    // Every unknown is some control point (so P has full column rank).
    std::vector<bool> seen(static_cast<size_t>(c0.unknowns), false);
    for (long long i : c0.identity)
      if (i >= 0) seen[static_cast<size_t>(i)] = true;
    EXPECT_EQ(std::count(seen.begin(), seen.end(), true), c0.unknowns);
  }
}

TEST(GridRefinement, C1SplinesAreC1AcrossHangingFacesAndContainTheCoarseOnes) {
  const BernsteinGrid g = Refined();
  const int k = 3;
  const long long n = NumBernsteinControlPoints(k);
  std::mt19937 rng(13);
  std::normal_distribution<double> z(0.0, 1.0);
  const Eigen::MatrixXd N = BernsteinSplineBasis(g, k, 1);
  ASSERT_GT(N.cols(), 0);
  Eigen::VectorXd c(N.cols());
  for (long long i = 0; i < c.size(); ++i) c[i] = z(rng);
  const Eigen::VectorXd b = N * c;
  double worst_value = 0, worst_gradient = 0;
  for (const FacePoint& f : InteriorFacePoints(g, &rng)) {
    Vec g1, g2;
    worst_value = std::max(worst_value, std::abs(Value(g, k, b, f.inner, f.x, &g1) -
                                                 Value(g, k, b, f.outer, f.x, &g2)));
    worst_gradient = std::max(worst_gradient, (g1 - g2).norm());
  }
  EXPECT_LT(worst_value, 1e-10);
  EXPECT_LT(worst_gradient, 1e-8);
  // Nesting: a C1 spline of the unrefined grid, re-expressed on the refined tetrahedra, satisfies
  // every row of the refined grid; the refined space is strictly larger.
  const BernsteinGrid coarse = Base(2, 1, 1);
  const Eigen::MatrixXd Nc = BernsteinSplineBasis(coarse, k, 1);
  EXPECT_GT(N.cols(), Nc.cols());
  Eigen::VectorXd cc(Nc.cols());
  for (long long i = 0; i < cc.size(); ++i) cc[i] = z(rng);
  const Eigen::VectorXd bc = Nc * cc;
  Eigen::VectorXd bf(g.NumTetrahedra() * n);
  for (long long t = 0; t < g.NumTetrahedra(); ++t) {
    const auto corners = Corners(g, t);
    double tau[4];
    const Vec centroid = (corners[0] + corners[1] + corners[2] + corners[3]) / 4;
    const long long tc = coarse.Locate(centroid.data(), tau);
    const Tetrahedron tet = coarse.TetrahedronOf(tc);
    Eigen::Matrix4d a;
    for (int i = 0; i < 4; ++i) {
      tet.Barycentric(corners[i].data(), tau);
      a.row(i) << tau[0], tau[1], tau[2], tau[3];
    }
    bf.segment(t * n, n) = ReexpressionMatrix(k, a) * bc.segment(tc * n, n);
  }
  EXPECT_LE(ContinuityDefect(g, k, 1, bf.data()), 1e-12);
}

TEST(GridRefinement, SharpFacesDropOnlyTheirC1Rows) {
  BernsteinGrid g = Refined();
  const int k = 3;
  const ContinuityRows all = BernsteinContinuityRows(g, k, 0, 1);
  const long long dim = BernsteinSplineBasis(g, k, 1).cols();
  g.sharp.assign(static_cast<size_t>(g.NumTetrahedra()), 0);
  for (long long t = 0; t < 12; ++t) g.sharp[t] = 0xF;  // every face of leaves 0 and 1
  const ContinuityRows kept = BernsteinContinuityRows(g, k, 0, 1);
  const ContinuityRows with = BernsteinContinuityRows(g, k, 0, 1, true);
  EXPECT_EQ(with.C.rows(), all.C.rows());
  EXPECT_LT(kept.C.rows(), all.C.rows());
  long long c0_rows = 0, c0_kept = 0;
  for (size_t r = 0; r < all.order.size(); ++r) c0_rows += all.order[r] == 0;
  for (size_t r = 0; r < kept.order.size(); ++r) {
    c0_kept += kept.order[r] == 0;
    EXPECT_TRUE(kept.order[r] == 0 || !kept.sharp[r]);
  }
  EXPECT_EQ(c0_kept, c0_rows);
  EXPECT_GT(BernsteinSplineBasis(g, k, 1).cols(), dim);
}

TEST(GridRefinement, RefinedMeshWithSharpFacesRoundTripsThroughJson) {
  BernsteinGrid g = Refined();
  g.sharp.assign(static_cast<size_t>(g.NumTetrahedra()), 0);
  g.sharp[3] = 0x5;
  const int k = 2;
  std::vector<double> b(static_cast<size_t>(g.NumTetrahedra() * NumBernsteinControlPoints(k)));
  for (size_t i = 0; i < b.size(); ++i) b[i] = 0.01 * static_cast<double>(i % 37) - 0.1;
  Model m;
  m.SetRoot(m.AddBernsteinMesh(k, g, 1, b));
  const nlohmann::json j = ModelToJson(m);
  EXPECT_EQ(j["root"]["grid"]["splits"], kRefinedSplits);
  EXPECT_EQ(j["root"]["c0_faces"], nlohmann::json::parse("[[3, 0], [3, 2]]"));
  const Model back = ModelFromJson(j);
  const ModelNode& node = back.nodes()[back.root()];
  EXPECT_EQ(SplitsOf(node.grid.refinement), SplitsOf(g.refinement));
  EXPECT_TRUE(node.grid.IsSharp(3, 2));
  EXPECT_FALSE(node.grid.IsSharp(3, 1));
  std::mt19937 rng(2);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int n = 0; n < 50; ++n) {
    const Vec x = g.BoxMin() + (g.BoxMax() - g.BoxMin()).cwiseProduct(Vec(u(rng), u(rng), u(rng)));
    EXPECT_EQ(back.Value(x), m.Value(x));
  }
  // Bad refinements name the field.
  nlohmann::json bad = j;
  bad["root"]["grid"]["splits"] = "10";
  try {
    ModelFromJson(bad);
    ADD_FAILURE() << "accepted";
  } catch (const std::exception& e) {
    EXPECT_NE(std::string(e.what()).find("root.grid.splits"), std::string::npos) << e.what();
  }
  bad = j;
  bad["root"]["c0_faces"] = nlohmann::json::parse("[[3, 4]]");
  EXPECT_THROW(ModelFromJson(bad), std::exception);
}

}  // namespace
}  // namespace implicitfit
