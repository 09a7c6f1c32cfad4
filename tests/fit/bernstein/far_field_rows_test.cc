// fit/bernstein/far_field_rows.h: where the far-field rows lie. On a uniform grid of 2^3 unit
// cubes they are the h/2 lattice (5^3 points); with the far corner cube split once, that cube's
// rows are the lattice of its children's half edge (spacing 1/4: 5^3 points in it, of which 3^3
// are on the h/2 lattice already), and no other row moves. Counted by enumeration, not by the
// code under test; one data point near the origin keeps every lattice point outside the band.
#include "fit/bernstein/far_field_rows.h"

#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <tuple>

#include "model/bernstein/grid_refinement.h"

namespace implicitfit {
namespace {

using Vec = Eigen::Vector3d;

BernsteinGrid TwoCubeGrid() {
  BernsteinGrid g;
  g.origin = Vec::Zero();
  g.cell = 1.0;
  g.cells = {2, 2, 2};
  return g;
}

// The rows' points in units of 1/4 (every row must sit on that lattice).
std::set<std::tuple<int, int, int>> QuarterLattice(const std::vector<FarFieldRow>& rows) {
  std::set<std::tuple<int, int, int>> out;
  for (const FarFieldRow& r : rows) {
    const Vec q = 4 * r.x;
    const Vec rounded = q.array().round();
    EXPECT_LT((q - rounded).norm(), 1e-12) << r.x.transpose();
    out.insert({int(rounded[0]), int(rounded[1]), int(rounded[2])});
  }
  return out;
}

TEST(FarFieldRows, UniformGridUsesTheHalfCellLattice) {
  const std::vector<Vec> points = {Vec(0.1, 0.1, 0.1)};
  const std::vector<Vec> normals = {Vec(0, 0, 1)};
  const auto rows = FarFieldRows(TwoCubeGrid(), points, normals, 0.05, 0.5, 0, 1, nullptr);
  ASSERT_EQ(rows.size(), 125u);
  const auto lattice = QuarterLattice(rows);
  EXPECT_EQ(lattice.size(), 125u);  // no point twice
  for (const auto& [i, j, l] : lattice) EXPECT_TRUE(i % 2 == 0 && j % 2 == 0 && l % 2 == 0);
  // On the box faces and beside the data (more than 60 degrees off the normal) the target is
  // the distance (outside), elsewhere Hoppe's (x - p) . n.
  for (const FarFieldRow& r : rows) {
    const bool on_box = (r.x.array() == 0).any() || (r.x.array() == 2).any();
    EXPECT_EQ(r.on_box, on_box) << r.x.transpose();
    const double distance = (r.x - points[0]).norm(), hoppe = r.x.z() - 0.1;
    const bool beside = std::abs(hoppe) < 0.5 * distance;  // beside the data: outside
    EXPECT_NEAR(r.target, on_box || beside ? distance : hoppe, 1e-12) << r.x.transpose();
  }
}

TEST(FarFieldRows, RefinedLeavesGetRowsAtTheirOwnSpacing) {
  BernsteinGrid grid = TwoCubeGrid();
  // Base cube 7 = (1, 1, 1) split into 8 children of edge 1/2.
  grid.refinement = RefinementFromSplits(grid.cells, "0000000100000000");
  ASSERT_EQ(grid.NumLeaves(), 15);
  const std::vector<Vec> points = {Vec(0.1, 0.1, 0.1)};
  const std::vector<Vec> normals = {Vec(0, 0, 1)};
  const auto rows = FarFieldRows(grid, points, normals, 0.05, 0.5, 0, 1, nullptr);
  const auto lattice = QuarterLattice(rows);
  EXPECT_EQ(lattice.size(), rows.size());
  EXPECT_EQ(rows.size(), 125u + 125u - 27u);
  for (const auto& [i, j, l] : lattice) {
    const bool in_split_cube = i >= 4 && j >= 4 && l >= 4;
    if (!in_split_cube) {
      EXPECT_TRUE(i % 2 == 0 && j % 2 == 0 && l % 2 == 0) << i << j << l;
    }
  }
  // Every quarter-lattice point of the split cube is there.
  for (int i = 4; i <= 8; ++i)
    for (int j = 4; j <= 8; ++j)
      for (int l = 4; l <= 8; ++l) EXPECT_TRUE(lattice.count({i, j, l})) << i << j << l;
}

TEST(FarFieldRows, PointsWithinTheBandGetNoRow) {
  const std::vector<Vec> points = {Vec(1, 1, 1)};
  const std::vector<Vec> normals = {Vec(0, 0, 1)};
  // Band 0.6: the centre and its 6 neighbours at 0.5 are dropped; the 12 at 0.707 are kept.
  const auto rows = FarFieldRows(TwoCubeGrid(), points, normals, 0.6, 0.5, 0, 1, nullptr);
  EXPECT_EQ(rows.size(), 125u - 7u);
  for (const FarFieldRow& r : rows) EXPECT_GT((r.x - points[0]).norm(), 0.6);
}

}  // namespace
}  // namespace implicitfit
