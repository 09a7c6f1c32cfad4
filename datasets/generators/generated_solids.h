// Generated CAD-like solids with known truth (issue 14's tests and bench/solid_comparison):
// smooth-CSG models whose fillets are Li & Phillips blends (order 3), the distinct surfaces
// `detect` would find in their scans, and ground-truth labels of sampled points.
//   rounded box      intersection of 6 planes (half sizes 1, 0.7, 0.5), delta 0.2, eps 0.12
//   plate with bore  difference(sharp box 1 x 1 x 0.25 half sizes, cylinder r 0.4 along z),
//                    delta 0.15, eps 0.1 (the bore's edges filleted)
//   boss on slab     union(sharp slab 1 x 1 x 0.2, sharp boss: cylinder r 0.35 between the slab's
//                    bottom and z = 0.8), delta 0.15, eps 0.1 (the boss's foot filleted)
// Parts for the points-only runs (issue 24: scans without normals or labels, `detect` first):
//   flanged shaft    union(flange: cylinder r 1, 0 < z < 0.3; shaft: cylinder r 0.45,
//   with blind bore  0.25 < z < 1.5), delta 0.1, eps 0.06 (the shaft's foot filleted), minus a
//                    blind bore (cylinder r 0.2, z > 0.8), sharp
//   L-bracket        box 2 x 1.2 x 1.2 (x, y, z from -1, -0.6, 0) minus the notch x > -0.7,
//                    z > 0.3 (its edge rounded: smooth intersection, delta 0.12, eps 0.08: the
//                    bracket's inner corner filleted), minus a through hole along z (r 0.2 at
//                    x = 0.35) and one along x (r 0.18 at z = 0.8), sharp
//   dome on plate    union(plate 2 x 2 x 0.3 from z = 0; dome: sphere r 0.6 centred at z = 0.2
//                    above z = 0.2), delta 0.1, eps 0.06 (the dome's foot filleted), minus two
//                    through holes (r 0.12 at (0.7, 0.7) and (-0.7, -0.7)), sharp
// Each bottom plane that two solids of a smooth union share is moved inside the other solid by
// more than delta + eps, so no face bulges (a smooth union of coplanar faces bulges by delta/4).
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "datasets/clouds/point_cloud.h"
#include "model/model.h"

namespace implicitfit {

struct GeneratedSolid {
  std::string name;
  Model truth;
  std::vector<Model> primitives;  // distinct surfaces (one-node models), as detect would find them
  double fillet_delta = 0.0;      // delta of the truth's one smooth blend
  Eigen::Vector3d box_min, box_max;  // a box around the solid (sampling box)
};

GeneratedSolid RoundedBoxSolid();
GeneratedSolid PlateWithFilletedBoreSolid();
GeneratedSolid BossOnSlabSolid();
GeneratedSolid FlangedShaftSolid();
GeneratedSolid LBracketSolid();
GeneratedSolid DomeOnPlateSolid();
// The first three (issue 14's): their label-started rows and tests.
std::vector<GeneratedSolid> AllGeneratedSolids();
// The three parts above (issue 24's points-only runs).
std::vector<GeneratedSolid> GeneratedParts();

// Label of each point: the primitive within `band` of the point whose gradient is within
// acos(0.999) of the point's normal (the nearest when several), -1 otherwise (fillets, outliers).
std::vector<int> GroundTruthLabels(const GeneratedSolid& solid, const PointCloud& cloud,
                                   double band);

}  // namespace implicitfit
