// Far-field rows of the patch-mesh fit (fit/bernstein/bernstein_mesh_fitter.h, step 1).
// Far-field rows: at the points x of a lattice of spacing half a leaf's edge (h/2 on a uniform
// grid; h / 2^(L+1) in a refined leaf of level L, so that finer leaves get rows as dense as
// their cells) farther than `band` from every input point, the target f(x) = (x - p) . n_p
// with p the nearest input point (Hoppe's signed tangent-plane distance), so that f keeps the
// outside/inside sign of the closest data away from the surface and no spurious sheet crosses
// empty cells; on the faces of the grid box the target is +|x - p| instead (outside), so that
// f > 0 on the whole box boundary and the zero set closes inside the box (an open scan, e.g.
// oni's unscanned base, is capped instead of leaving the box). A lattice point x whose direction
// from p makes more than acos(beside_cos) (60 degrees) with n_p lies beside the data, beyond an
// open rim, rather than above or below it: the tangent-plane sign says nothing there, and the target is +|x - p| (outside) too, so that the
// cap of an open scan closes near its rim instead of at the box (oni: Chamfer 0.0227 -> 0.0209).
// With `winding` (the default, MeshFitOptions::far_field_winding), the sign of a row off the
// box comes from the generalised winding number w of the cloud instead (fit/bernstein/winding_number.h:
// inside where w > 1/2), and its magnitude is at most |w - 1/2| / |grad w|, the first-order
// distance to the level w = 1/2: the tangent-plane test says nothing beyond an open rim and the
// "beside" rule capped oni's unscanned base where the data stopped sideways, 0.06 below the
// rim; w's level 1/2 spans the rim (flat for a planar rim) and the magnitude bound makes the
// targets one consistent signed distance across it, so the cap follows that level instead of
// wobbling between lattice points (see the header for the figures).
// Row weight (not on the box): min(1, (distance to the data / (ramp h))^ramp_power), see the
// header. Nearest point by brute force (lattice x points: below 10^9 operations for the grids
// used here; fit/ has no spatial index).
#pragma once

#include <Eigen/Core>
#include <vector>

#include "fit/bernstein/winding_number.h"
#include "model/bernstein/bernstein_mesh.h"

namespace implicitfit {

struct FarFieldRow {
  Eigen::Vector3d x;
  double target;
  bool on_box = false;
  double weight = 1.0;  // relative weight (far_field_ramp)
};

std::vector<FarFieldRow> FarFieldRows(const BernsteinGrid& grid,
                                      const std::vector<Eigen::Vector3d>& points,
                                      const std::vector<Eigen::Vector3d>& normals, double band,
                                      double beside_cos, double ramp, double ramp_power,
                                      const WindingNumber* winding);

// Far-field points where f has the opposite sign of the row's target (or is 0).
long long FarFieldSignErrors(const BernsteinGrid& grid, int k, const std::vector<double>& b,
                             const std::vector<FarFieldRow>& rows, bool box_only = false);

}  // namespace implicitfit
