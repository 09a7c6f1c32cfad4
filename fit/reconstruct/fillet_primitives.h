// Detected surfaces that are fillets between two faces (`implicitfit reconstruct`'s second
// attempt, fit/reconstruct/solid_reconstruction.h).
//
// `detect` fits a rounded edge with a surface of its own (a cylinder along a box's edge, a sphere
// or a cone at its corner). As literals of the Boolean expression they make it exact where the
// rounding is circular (a torus around a bore's rim), but a box whose edges and corners are all
// rounded gives twelve cylinders and eight corner pieces whose cells no plane separates (the
// generated rounded box: per-primitive inside/outside agreement 0.49 next to them). A smooth
// blend of the faces' intersection (model/blends) models the same rounding with two numbers, its
// range delta and epsilon, fitted in step 5 from the rounding's own points.
//
// A primitive k is fillet-like when at least `share` of its assigned points x (normal n) lie
// between two larger primitives a and b (more assigned points than k): both within `reach` of x
// (first-order distance), their faces not parallel (|g_a . g_b| < 0.95, unit gradients), and n
// leaning toward both faces' outward sides, n . s_a g_a > 0.05 and n . s_b g_b > 0.05 (s the
// primitive's side vote: which way its material lies). A rounding's normal turns from one
// face's normal to the other's, so it satisfies both; a face meeting another at an edge has
// n . g = 0 or less with it (a boss's side and the slab under it, a bore and the plate's faces),
// and a surface far from any crease (a dome) is not within reach of two faces.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "fit/reconstruct/point_assignment.h"
#include "model/model.h"

namespace implicitfit {

// Per primitive: true when it is fillet-like (header). Inactive primitives are never.
std::vector<bool> FilletLikePrimitives(const std::vector<Eigen::Vector3d>& points,
                                       const std::vector<Eigen::Vector3d>& normals,
                                       const std::vector<Model>& primitives,
                                       const PointAssignment& assignment, double reach,
                                       double share = 0.6);

}  // namespace implicitfit
