// Consistent signs for normals whose directions are known (estimated by PCA, or read from a
// file that does not orient them). Only signs change; every function returns how many
// normals it flipped.
//
// - Toward a viewpoint v (the scanner): n_i is flipped when n_i . (v - p_i) < 0, so every normal
//   faces the sensor that saw its point.
// - Minimum spanning tree propagation (Hoppe, DeRose, Duchamp, McDonald, Stuetzle 1992, §3.3):
//   over the symmetric neighbour graph with edge cost 1 - |n_i . n_j|, grow a minimum spanning
//   tree (Prim) from a seed and flip each newly reached normal that opposes its tree parent,
//   so orientation travels along the smoothest paths first. Each connected component is seeded
//   at its point of largest x whose normal gets the outward guess n . (p - c) > 0, c the
//   centroid of the cloud (for the max-x point, p - c points out of the shape).
// - Detector: the fraction of neighbour pairs with nearly parallel lines (|n_i . n_j| > 0.5)
//   whose normals oppose (n_i . n_j < 0). About 0 for oriented normals of a surface sampled
//   finer than its thickness and curvature; about 0.5 for random signs.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <vector>

namespace implicitfit {

size_t OrientTowardViewpoint(const std::vector<Eigen::Vector3d>& points, const Eigen::Vector3d& viewpoint,
                             std::vector<Eigen::Vector3d>* normals);

size_t OrientByMinimumSpanningTree(const std::vector<Eigen::Vector3d>& points,
                                   const std::vector<std::vector<int>>& neighbours,
                                   std::vector<Eigen::Vector3d>* normals);

double OpposedNeighbourFraction(const std::vector<Eigen::Vector3d>& normals,
                                const std::vector<std::vector<int>>& neighbours);

}  // namespace implicitfit
