// Normals for clouds that lack them, and consistent orientation for all.
//
// Estimation (PCA): the normal at p_i is the eigenvector of the smallest eigenvalue of the
// covariance of p_i and its neighbours (neighbourhoods.h: k from the local density, between
// min_k and max_k). Its sign is then chosen by orientation (normal_orientation.h): toward the
// viewpoint when one is given (PCD VIEWPOINT, PLY camera: CloudFileInfo::viewpoint), else by
// minimum-spanning-tree propagation seeded with an outward guess, then corrected per smooth patch
// by a visibility vote (visibility_orientation.h).
//
// Normals read from a file are kept, but first checked: when more than
// `max_opposed_fraction` of nearly parallel neighbour pairs have opposite signs (random or
// per-patch signs, as many real files have), the file's directions are kept and their signs
// re-oriented the same way (viewpoint, else MST).
#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "datasets/normals/neighbourhoods.h"
#include "datasets/clouds/point_cloud.h"

namespace implicitfit {

struct NormalOptions {
  NeighbourhoodOptions neighbourhood;        // k from density: see neighbourhoods.h
  std::optional<Eigen::Vector3d> viewpoint;  // orient toward this (the scanner) when set
  bool reestimate = false;                   // ignore the cloud's normals and estimate new ones
  double max_opposed_fraction = 0.1;         // above this, file normals count as unoriented
  // After the MST: flip smooth patches that views from outside see from behind
  // (visibility_orientation.h); no effect with a viewpoint.
  bool visibility_vote = true;
};

struct NormalResult {
  // "read from file", "read from file, re-oriented toward viewpoint", "read from file,
  // MST-re-oriented", "estimated, oriented toward viewpoint" or "estimated, MST-oriented".
  std::string action;
  size_t estimated = 0;           // normals computed by PCA
  size_t flipped = 0;             // normals whose sign orientation changed
  double opposed_fraction = 0.0;  // detector value on the file's normals (0 when estimated)
  double mean_neighbours = 0.0;   // mean neighbourhood size used (0 when nothing was computed)
  size_t visibility_flipped_patches = 0;  // smooth patches the visibility vote reversed
  size_t duplicates = 0;  // points equal to an earlier one (also appended to `action`)
};

// Fills cloud->normals when empty (or when options.reestimate), and orients them. Throws
// std::invalid_argument for fewer than 3 points when normals have to be estimated.
// neighbourhoods (optional): receives the neighbourhoods the normals were estimated or checked
// with (FindNeighbourhoods with options.neighbourhood), so a caller that needs them too (the
// detector) does not search again; left empty for clouds of fewer than 2 points.
NormalResult EnsureOrientedNormals(PointCloud* cloud, const NormalOptions& options = {},
                                   Neighbourhoods* neighbourhoods = nullptr);

// Unoriented PCA normals (sign arbitrary), one per point.
std::vector<Eigen::Vector3d> EstimatePcaNormals(const std::vector<Eigen::Vector3d>& points,
                                                const Neighbourhoods& neighbourhoods);

// Surface variation (Pauly, Gross, Kobbelt 2002) of each point's neighbourhood:
// lambda_0 / (lambda_0 + lambda_1 + lambda_2) of the covariance above, 0 on a plane, up to 1/3
// for an isotropic blob; high on creases and corners, where the PCA normal is a blend.
std::vector<double> SurfaceVariation(const std::vector<Eigen::Vector3d>& points,
                                     const Neighbourhoods& neighbourhoods);

// Replaces the normals at `indices` (invalid in the file) by PCA normals, each signed to agree
// with the sum of its neighbours' valid normals. Throws std::invalid_argument when the cloud
// has fewer than 3 points.
void ReestimateNormalsAt(PointCloud* cloud, const std::vector<size_t>& indices,
                         const NeighbourhoodOptions& options = {});

}  // namespace implicitfit
