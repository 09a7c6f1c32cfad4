// Generated CAD-like solids with known truth (issue 14's tests and bench/solid_comparison):
// smooth-CSG models whose fillets are Li & Phillips blends (order 3), the distinct surfaces
// `detect` would find in their scans, and ground-truth labels of sampled points.
//   rounded box      intersection of 6 planes (half sizes 1, 0.7, 0.5), delta 0.2, eps 0.12
//   plate with bore  difference(sharp box 1 x 1 x 0.25 half sizes, cylinder r 0.4 along z),
//                    delta 0.15, eps 0.1 (the bore's edges filleted)
//   boss on slab     union(sharp slab 1 x 1 x 0.2, sharp boss: cylinder r 0.35 between the slab's
//                    bottom and z = 0.8), delta 0.15, eps 0.1 (the boss's foot filleted)
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
std::vector<GeneratedSolid> AllGeneratedSolids();

// Label of each point: the primitive within `band` of the point whose gradient is within
// acos(0.999) of the point's normal (the nearest when several), -1 otherwise (fillets, outliers).
std::vector<int> GroundTruthLabels(const GeneratedSolid& solid, const PointCloud& cloud,
                                   double band);

}  // namespace implicitfit
