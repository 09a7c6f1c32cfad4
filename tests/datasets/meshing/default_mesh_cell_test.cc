// The mesher's default cell (datasets/meshing/default_mesh_cell.h): longest / 100, or half the
// finest leaf of a Bernstein mesh with sharp faces (never coarser than longest / 64). Expected
// cells are counted by hand from the grids below.
#include "datasets/meshing/default_mesh_cell.h"

#include <gtest/gtest.h>

#include "model/bernstein/bernstein_patch.h"
#include "model/bernstein/grid_refinement.h"

namespace implicitfit {
namespace {

// A 2 x 1 x 1 grid of base cube 0.5: cube 0 split, its octant-7 child split again (finest leaf
// 0.5 / 4 = 0.125); 16 leaves, 96 tetrahedra.
BernsteinGrid RefinedGrid() {
  BernsteinGrid g;
  g.cell = 0.5;
  g.cells = {2, 1, 1};
  g.refinement = RefinementFromSplits(g.cells, "1" "0000000" "100000000" "0");
  return g;
}

Model MeshModelOf(const BernsteinGrid& grid) {
  Model m;
  const long long n = grid.NumTetrahedra() * NumBernsteinControlPoints(1);
  m.SetRoot(m.AddBernsteinMesh(1, grid, 0, std::vector<double>(n, 1.0)));
  return m;
}

TEST(DefaultMeshCell, HundredCellsWithoutCreases) {
  Model sphere;
  sphere.SetRoot(sphere.AddPrimitive(NodeType::kSphere, {0, 0, 0, 1}));
  EXPECT_DOUBLE_EQ(DefaultMeshCell(sphere, 3.0), 0.03);
  // A refined Bernstein mesh without sharp faces keeps the same default.
  EXPECT_DOUBLE_EQ(DefaultMeshCell(MeshModelOf(RefinedGrid()), 3.0), 0.03);
}

TEST(DefaultMeshCell, HalfTheFinestLeafOfAMeshWithCreases) {
  BernsteinGrid g = RefinedGrid();
  ASSERT_EQ(g.NumTetrahedra(), 96);
  g.sharp.assign(96, 0);
  g.sharp[5] = 1 << 2;  // one C0 face (which one does not matter)
  // Finest leaf 0.125: cell 0.0625 while longest / 64 is coarser (10 / 64 = 0.156).
  EXPECT_DOUBLE_EQ(DefaultMeshCell(MeshModelOf(g), 10.0), 0.0625);
  // A box of longest side 2: 2 / 64 = 0.03125 is finer than 0.0625 and wins.
  EXPECT_DOUBLE_EQ(DefaultMeshCell(MeshModelOf(g), 2.0), 0.03125);
  // Uniform grid of cube 0.5 with creases: 0.25 (longest 100: 1.56 / 64 coarser).
  BernsteinGrid uniform;
  uniform.cell = 0.5;
  uniform.cells = {2, 1, 1};
  uniform.sharp.assign(static_cast<size_t>(uniform.NumTetrahedra()), 0);
  uniform.sharp[0] = 1;
  EXPECT_DOUBLE_EQ(DefaultMeshCell(MeshModelOf(uniform), 100.0), 0.25);
}

}  // namespace
}  // namespace implicitfit
