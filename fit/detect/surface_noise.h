// Noise of a sampled oriented surface from its neighbourhoods, free of the curvature bias of a
// tangent-plane estimate. For a point p_i and a neighbour p_j with unit normals n_i, n_j (n_j
// flipped to agree with n_i), the distance of p_j to the tangent plane of p_i,
//   n_i . (p_j - p_i) = d^T H d / 2 + noise        (d the tangential offset, H the curvature),
// holds the sagitta of the surface; the normal turns by (n_j - n_i) . (p_j - p_i) = -d^T H d to
// second order, so the mid-normal distance
//   e_ij = (n_i + n_j) / 2 . (p_j - p_i)
// cancels the curvature term (exactly on a sphere) and leaves the noise. The cloud's noise is
//   sigma = 1.4826 median over the points of (median over their first 8 neighbours of |e_ij|)
// (MAD of a Gaussian). A tangent-plane estimate reads the sagitta d^2 / (2 R): 0.18 on a coarse
// noise-free CAD sample (spacing 1.75, radius 12.7) where the noise is 0.
// Every `stride`-th point is used; points without neighbours are skipped.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "datasets/clouds/neighbour_graph.h"

namespace implicitfit {

// neighbours: each point's nearest neighbours (itself excluded), nearest first. Returns 0 when no
// point has a neighbour.
double EstimateSurfaceNoise(const std::vector<Eigen::Vector3d>& points,
                            const std::vector<Eigen::Vector3d>& normals,
                            const NeighbourGraph& neighbours, size_t stride = 1);

}  // namespace implicitfit
