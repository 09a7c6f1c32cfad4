// Adaptive refinement of a Bernstein mesh's box grid (model/bernstein/bernstein_mesh.h): an octree
// in every base cube, whose leaves are Kuhn-split like the cubes of a uniform grid.
//
// Structure. Base cube c (index (l ny + j) nx + i) is the root of an octree; a node is a leaf or
// has 8 children, the cubes of half its edge, numbered by octant o = bx + 2 by + 4 bz (b_a = 1:
// the upper half along axis a). A leaf at level L (the base cubes are level 0) has edge
// h / 2^L and integer coordinates (i, j, l) in units of that edge from the grid's origin.
// Leaves are numbered base cube after base cube, each octree depth first with children in octant
// order; leaf q holds tetrahedra 6 q .. 6 q + 5 (same Kuhn order as a uniform cube).
//
// File form (docs/patch-mesh.md): the split flags in preorder, base cube after base cube, one
// character per node: '1' for a node with 8 children (followed by theirs), '0' for a leaf. A
// uniform grid is "000...0" (one '0' per base cube); the empty string also means uniform.
//
// Nesting (docs/maths.md G-1): the Kuhn split of a cube of edge h/2 refines that of edge h (their
// face planes x_a = m h/2, x_a - x_b = m h/2 contain those of the coarser split), so every
// tetrahedron of a leaf lies in exactly one tetrahedron of any coarser cube that contains it,
// and a finer leaf's face on a coarser leaf's face lies inside one of its triangles.
#pragma once

#include <array>
#include <string>
#include <vector>

namespace implicitfit {

// Deepest level a refinement may have (lattice coordinates stay below 2^31 for 200 base cubes).
constexpr int kMaxRefinementLevel = 12;

struct GridRefinement {
  std::vector<int> node;  // per node: index of its first child (8 in a row), or -1 - leaf index
  std::vector<int> root;  // per base cube: its root node
  std::vector<std::array<int, 4>> leaves;  // per leaf: level, i, j, l
  int max_level = 0;
  bool empty() const { return node.empty(); }
};

// Parses the split flags for a base grid of `cells` cubes; throws std::invalid_argument naming
// the problem (a character other than 0/1, too few or too many flags, a level beyond
// kMaxRefinementLevel).
GridRefinement RefinementFromSplits(const std::array<int, 3>& cells, const std::string& splits);
// The split flags of a refinement (the inverse of RefinementFromSplits).
std::string SplitsOf(const GridRefinement& refinement);
// The uniform refinement (every base cube a leaf).
GridRefinement UniformRefinement(const std::array<int, 3>& cells);
// Splits every leaf q with split[q] into its 8 children; parent_of (if given) receives, for
// every leaf of the result, the leaf of `refinement` that holds it.
GridRefinement SplitLeaves(const std::array<int, 3>& cells, const GridRefinement& refinement,
                           const std::vector<bool>& split, std::vector<int>* parent_of = nullptr);
// The leaf containing the lattice point p (units of h / 2^units from the origin, units >=
// max_level; clamped into the box; on a face between leaves the upper one along each axis).
int LeafAt(const std::array<int, 3>& cells, const GridRefinement& refinement,
           const std::array<long long, 3>& p, int units);
// Leaves to split so that leaves sharing a face, an edge or a corner differ by at most one
// level (2:1 balance), given those already marked: the marks grown until balanced.
std::vector<bool> BalanceSplits(const std::array<int, 3>& cells, const GridRefinement& refinement,
                                std::vector<bool> split);

}  // namespace implicitfit
