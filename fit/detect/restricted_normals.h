// Normals re-estimated from a subset of the cloud: the points a first detection pass left free.
//
// A narrow surface between two detected ones (a cylinder ring one or two rows high between two
// faces) has its estimated normals smeared by the neighbouring faces: the PCA of a point's
// neighbourhood mixes in their points. Once those faces hold their points, the neighbourhood
// restricted to the free points is the narrow surface alone, and its PCA normal is the surface's.
// For each free point i: the eigenvector of the smallest eigenvalue of the covariance of i and
// its free neighbours j (neighbours[i], all of them), signed to agree with normals[i]. The
// normal is kept as given when i has fewer than 4 free neighbours or when they do not span a
// plane (eigenvalues l0 <= l1 <= l2 with l1 < 4 l0: a single row of points, a line, or a blob).
#pragma once

#include <Eigen/Core>
#include <vector>

#include "datasets/clouds/neighbour_graph.h"

namespace implicitfit {

std::vector<Eigen::Vector3d> RestrictedNormals(const std::vector<Eigen::Vector3d>& points,
                                               const std::vector<Eigen::Vector3d>& normals,
                                               const NeighbourGraph& neighbours,
                                               const std::vector<char>& free);

}  // namespace implicitfit
