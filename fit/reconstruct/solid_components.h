// The pieces of a solid on a grid, and which of them the scan supports (the third check of
// fit/reconstruct/solid_verification.h).
//   1. the sign of f is found at the nodes of a regular grid of cell h over a box that holds
//      the solid (exactly Model::Value's sign; sharp operators short-circuit: an intersection
//      is outside at its first child outside, a union inside at its first child inside);
//   2. inside nodes (f < 0) are joined into components through their 26 neighbours, outside
//      nodes (f >= 0) through their 6 face neighbours (the usual pairing of digital topology, so
//      a surface separates exactly one inside from one outside component); the outside
//      components that reach the grid's faces are the space around the solid, every other one
//      is a cavity: a closed shell of empty space inside the material (e.g. a void left where
//      the hexagon socket's planes continue into a screw's shank);
//   3. a scan point supports the surface where it lies: when its first-order distance
//      |f| / |grad f| is at most `band`, the grid nodes of its cell and of the cells around it
//      (4 x 4 x 4 nodes) are marked as seen, and the components among its cell's 8 corners (the
//      4 x 4 x 4 block when its cell has one sign only) count it;
//   4. a component's boundary is the set of grid edges from one of its nodes to a node of the
//      other sign; its coverage is the share of those edges with a seen end. A component is
//      supported when its coverage is at least `min_coverage` and at least `min_points` points
//      count it.
// Pieces thinner than a cell may be missed, as in a mesh of the same grid.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "model/model.h"

namespace implicitfit {

struct SolidPiece {
  bool cavity = false;  // false: a component of the solid; true: an enclosed pocket of space
  int nodes = 0;        // grid nodes in it
  double volume = 0.0;  // nodes * h^3
  Eigen::Vector3d lo = Eigen::Vector3d::Zero(), hi = Eigen::Vector3d::Zero();  // its nodes' box
  Eigen::Vector3d witness = Eigen::Vector3d::Zero();  // of 64 of its nodes, the largest |f|
  int support_points = 0;
  int boundary_edges = 0, covered_edges = 0;
  double coverage = 0.0;
  bool supported = false;
};

struct SolidComponentOptions {
  double band = 0.0;          // 0: one cell
  double min_coverage = 0.1;  // share of the boundary next to scan points
  int min_points = 3;
  long max_grid_points = 16L << 20;  // refuse finer grids (the cell is made larger instead)
  int num_threads = 0;               // 0: every core
};

struct SolidComponents {
  Eigen::Vector3d lo = Eigen::Vector3d::Zero(), hi = Eigen::Vector3d::Zero();
  double cell = 0.0;
  int grid[3] = {0, 0, 0};
  int solids = 0, cavities = 0;
  bool touches_box = false;      // some inside node lies on the grid's faces
  std::vector<SolidPiece> pieces;  // solids first (largest first), then cavities
};

// The grid spans [lo, hi] with spacing `cell` (enlarged when the grid would pass
// options.max_grid_points).
SolidComponents FindSolidComponents(const Model& model, const Eigen::Vector3d& lo,
                                    const Eigen::Vector3d& hi, double cell,
                                    const std::vector<Eigen::Vector3d>& points,
                                    const SolidComponentOptions& options = {});

}  // namespace implicitfit
