// Extra half-spaces for the separation of fit/reconstruct/csg_separation.h when the detected primitives alone
// cannot give a bounded solid that agrees with the oriented cloud (`implicitfit reconstruct`).
//
// Separators (Shapiro & Vossler's separating half-spaces). The arrangement of the primitives
// may put material and empty space in one cell: a cylinder's inside continues beyond the end of
// the boss it bounds (Fit4CAD PC124: the stem's cylinder runs through the ball and out of its
// top), the centre of a slab whose sides are quarter-round cylinders and corner spheres has the
// sign vector of the space beyond its corners (PC131: no detected surface lies on the planes
// x = +-13, y = +-13 that bound it). Such a cell holds many inside and many outside samples. A
// separator is a plane that splits one such cell's samples best: a decision stump, the
// threshold c along a direction d minimising the misclassified samples when d . x < c is
// called inside and d . x > c outside (or the reverse); c is the middle of the gap between the
// two neighbouring projections. Directions: the normals of the planes and the axes of the
// cylinders, cones and tori of the scene (the part's own directions) and the coordinate axes.
// Separators are fixed planes in the model (no data lies on them; the fitter keeps them).
//
// Closures. A scan is often open: the bottom of a part on a table is never seen, the ground
// under it is a one-sided sheet. No solid made of the seen surfaces alone is then bounded.
// The closure box is the smallest box around the assigned points in the part's own frame (the
// normal of the plane with most points, then the most orthogonal other plane's, then their
// cross product; the principal axes of the points without two such planes), enlarged by
// `margin` on every side; its six faces are added as literals, every cell outside the box is
// outside (the solid is declared to lie in it), and the separation keeps a closure literal only
// where the data leave the solid open in that direction. The closure faces that end up in the
// expression are not measured surfaces: the report lists them.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "model/model.h"

namespace implicitfit {

// A plane literal: f = n . x - offset (n unit), material where f < 0.
struct PlaneLiteral {
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();
  double offset = 0.0;
  Model ToModel(const std::string& name) const;  // a fixed plane node
};

// Unit directions for separators: plane normals and the axes of cylinders, cones and tori of
// the given primitives, then x, y, z; directions within 1 degree of an earlier one are dropped.
std::vector<Eigen::Vector3d> SeparatorDirections(const std::vector<Model>& primitives);

struct StumpSplit {
  bool found = false;
  PlaneLiteral plane;  // inside samples on its f < 0 side
  int errors = 0;      // samples on the wrong side
};

// The best decision stump over the directions for samples x[i] labelled inside[i].
StumpSplit BestStump(const std::vector<Eigen::Vector3d>& x, const std::vector<bool>& inside,
                     const std::vector<Eigen::Vector3d>& directions);

// The frame of the closure box (rows: unit axes) from the scene's planes and their point
// counts, or from the principal axes of the points.
Eigen::Matrix3d ClosureFrame(const std::vector<Model>& primitives,
                             const std::vector<int>& assigned_points,
                             const std::vector<Eigen::Vector3d>& points);

// The six faces of the box around the points in the frame, enlarged by margin: -a0, +a0, -a1,
// +a1, -a2, +a2 (each outward).
std::vector<PlaneLiteral> ClosureBox(const Eigen::Matrix3d& frame,
                                     const std::vector<Eigen::Vector3d>& points, double margin);

}  // namespace implicitfit
