// Consistent signs for normals whose directions are known (estimated by PCA, or read from a
// file that does not orient them). Only signs change; every function returns how many
// normals it flipped.
//
// - Toward a viewpoint v (the scanner): n_i is flipped when n_i . (v - p_i) < 0, so every normal
//   faces the sensor that saw its point.
// - Minimum spanning tree propagation (Hoppe, DeRose, Duchamp, McDonald, Stuetzle 1992, §3.3):
//   over the symmetric graph of each point's 8 nearest neighbours (a sparse graph, as Hoppe's
//   Riemannian graph; wider ones bridge thin gaps between surfaces) with edge cost 1 - |a_ij|, grow
//   a minimum spanning tree (Prim) from a seed and flip each newly reached normal n_j whose
//   agreement a_ij with its tree parent is negative, so orientation travels along the most reliable
//   edges first. Hoppe uses a_ij = n_i . n_j; here a_ij = (M n_i) . n_j with M the reflection
//   across the plane bisecting p_i p_j (König & Gumhold, "Consistent propagation of normal
//   orientations in point clouds", VMV 2009): exact for two points of a sphere, and right across
//   symmetric creases and between the two sides of thin sheets, where n_i . n_j has the wrong sign.
//   Each connected component is seeded at its point of largest x, whose normal gets the outward
//   guess n_x >= 0 (at the extreme point in x of a closed shape, the outward normal is +x). Known
//   limit: surfaces that pass through each other (two overlapping full spheres, as in
//   cgal_spheres_10.ply) can come out with one of them inverted.
// - Detector: the fraction of neighbour pairs with nearly parallel lines (|n_i . n_j| > 0.5)
//   whose normals oppose (n_i . n_j < 0). About 0 for oriented normals of a surface sampled
//   finer than its thickness and curvature; about 0.5 for random signs.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <vector>

#include "datasets/clouds/neighbour_graph.h"

namespace implicitfit {

size_t OrientTowardViewpoint(const std::vector<Eigen::Vector3d>& points,
                             const Eigen::Vector3d& viewpoint,
                             std::vector<Eigen::Vector3d>* normals);

size_t OrientByMinimumSpanningTree(const std::vector<Eigen::Vector3d>& points,
                                   const NeighbourGraph& neighbours,
                                   std::vector<Eigen::Vector3d>* normals);

// The MST's agreement a_ij = (M n_i) . n_j, M the reflection across the plane bisecting p_i p_j
// (n_i . n_j when the points coincide).
double MirroredAgreement(const std::vector<Eigen::Vector3d>& points,
                         const std::vector<Eigen::Vector3d>& normals, int i, int j);

// The MST's graph: each point joined to its first 8 neighbours, made symmetric.
std::vector<std::vector<int>> SymmetricNeighbourGraph(
    const NeighbourGraph& neighbours);

// The MST's propagation on its own: the seeds keep their signs and are marked visited, then
// Prim's tree grows from all of them at once into the unvisited points (marking them), each
// reached normal flipped when its agreement with its tree parent is negative.
size_t PropagateOrientation(const std::vector<Eigen::Vector3d>& points,
                            const std::vector<std::vector<int>>& graph,
                            const std::vector<int>& seeds, std::vector<char>* visited,
                            std::vector<Eigen::Vector3d>* normals);

double OpposedNeighbourFraction(const std::vector<Eigen::Vector3d>& normals,
                                const NeighbourGraph& neighbours);

}  // namespace implicitfit
