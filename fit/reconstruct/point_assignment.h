// Which primitive each point of a scan lies on, and which primitives a solid needs
// (`implicitfit reconstruct`, steps 1 and 1b of fit/reconstruct/solid_reconstruction.h).
//
// Assignment: point i goes to the primitive k with the smallest |f_k| / |grad f_k| / tau_k
// below 1 whose gradient is within acos(0.8) = 37 degrees of the point's normal (either sign);
// none when no primitive qualifies. Each assigned point votes for its primitive's side: +1 when
// n . grad f_k > 0 (material inside f_k < 0), -1 otherwise.
//
// Redundant primitives (crease bands). Where two faces meet at a sharp edge, normals estimated
// from the points (PCA over a neighbourhood) blend both faces' normals over a band a few
// spacings wide; `detect` then fits these points with extra surfaces (tilted planes along edges,
// cones at corners, tori around the rims of holes, huge spheres on face borders: Fit4CAD-like
// generated parts gave 15 to 25 of them besides 7 to 10 faces). They are no faces of the part,
// and as literals they split the solid into spurious terms, some unbounded. Their points lie
// on the faces they border: a primitive is redundant when at least `share` of its assigned
// points lie within band_j = max(2.5 rms_j, floor) of some larger kept primitive j (by distance
// only: the normals are what is wrong there). Primitives are tested from the smallest; a
// redundant one is dropped and its points are assigned again among the others. A fillet is
// kept: its points leave the faces it joins by up to rho (1 - cos 45 deg) (rho its radius), so
// only those within about 30 degrees of either tangency are within 2.5 sigma of a face (about
// two thirds of them when rho is 20 sigma), and a real face of another surface (a bore's floor)
// is not near any other face. Fillets narrower than a few sigma look like creases and are
// dropped: the solid then keeps the sharp edge.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "model/model.h"

namespace implicitfit {

struct PointAssignment {
  std::vector<int> label;          // per point: primitive index, -1 none
  std::vector<int> assigned;       // per primitive: number of points
  std::vector<double> side_vote;   // per primitive: sum of the points' votes
  int unassigned = 0;
};

// Primitives with active[k] false get no point.
PointAssignment AssignPoints(const std::vector<Eigen::Vector3d>& points,
                             const std::vector<Eigen::Vector3d>& normals,
                             const std::vector<Model>& primitives, const std::vector<double>& tau,
                             const std::vector<bool>& active);

// Marks redundant primitives (header) false in *active; returns how many it marked.
int DropRedundantPrimitives(const std::vector<Eigen::Vector3d>& points,
                            const std::vector<Model>& primitives, const std::vector<double>& band,
                            const PointAssignment& assignment, double share,
                            std::vector<bool>* active);

}  // namespace implicitfit
