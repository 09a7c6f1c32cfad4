// Generated CAD-like solids with sharp edges, fillets and a freeform face, for the patch-mesh
// benchmark (bench/surface_comparison) and tests: smooth-CSG model trees (model/model.h) whose
// sharp edges are exact min/max (order 0) and whose fillets are Li & Phillips blends (order 3),
// each turned by one generic rotation (axis (1, 2, 3), 0.5 rad) so that no crease runs along
// the axes of a fitting grid. Sizes are about 2 along the longest side.
//   bracket         L-shaped union of two blocks (the inner corner filleted, delta 0.15) minus a
//                   sharp bore of radius 0.22 through the upright
//   domed block     a block whose top is a paraboloid dome (curvature 0.6): sharp curved creases
//                   where the dome meets the sides
//   flange          a disc of radius 1 and height 0.3 with a boss of radius 0.4 up to z = 0.8
//                   (its foot filleted, delta 0.12), a sharp bore of radius 0.2 through both
//   chamfered block a block with two 45-degree chamfers along two edges (dihedral angles of
//                   135 degrees) and the other edges sharp
//   saddle block    a block whose top is a saddle z = 0.35 + 0.25 (x^2 - y^2) / 2 (a freeform
//                   face of both curvature signs, general quadric) meeting the sides sharply
// and, held out (added after every setting of the patch-mesh fitter was chosen, and not part of
// AllCadSolids; turned by its own rotation, axis (2, -1, 1), 0.7 rad):
//   held-out stepped part  two sharp steps (a concave sharp crease between them), the upper
//                   step's top a freeform quadric z = 0.45 + 0.12 x y - 0.08 y^2, and a sharp
//                   bevel across the lower step's far end (normal 30 degrees up from +x)
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "model/model.h"

namespace implicitfit {

struct CadSolid {
  std::string name;
  Model truth;
  Eigen::Vector3d box_min, box_max;  // a box around the (rotated) solid, for sampling
};

CadSolid BracketSolid();
CadSolid DomedBlockSolid();
CadSolid FlangeSolid();
CadSolid ChamferedBlockSolid();
CadSolid SaddleBlockSolid();
std::vector<CadSolid> AllCadSolids();
CadSolid HeldOutPartSolid();

// The rotation every solid is turned by.
Eigen::Matrix3d CadSolidRotation();

}  // namespace implicitfit
