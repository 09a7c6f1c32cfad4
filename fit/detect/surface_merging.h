// The detector's last word on "one surface or two" (fit/detect/primitive_detector.h, final
// stage), for planes:
//
// Offset split. A plane whose support is two parallel sheets (a thin plate seen from both sides,
// two sheets closer than the band) reads a residual distribution with two modes. The signed
// residuals r_i of its support (an evenly spread subset) get a one-dimensional two-Gaussian
// mixture by EM (means mu_1 < mu_2, scales s_1, s_2, weights w_1, w_2) and a single Gaussian; the
// plane is split into the two offset planes when the mixture wins by BIC,
//   -2 ln L_2 + 5 ln n < -2 ln L_1 + 2 ln n,
// its modes are apart, mu_2 - mu_1 > 2 (s_1 + s_2), and each holds at least 20% of the points
// (a heavy-tailed unimodal scatter fits a narrow and a wide component with the same mean: no
// split). Each point goes to the nearer offset plane; both are refitted by least squares.
//
// Same-surface merge. Pieces of one plane that the growth left apart (a wall of a multi-view
// stereo scan wanders by more than the band over its length; windows and occluders cut it) are
// merged when
//   their normals agree within kMergeAngleDeg (2 deg),
//   they tile the plane side by side rather than overlap: fewer than 25% of the smaller piece's
//     points have a point of the other among their 8 nearest neighbours (two parallel sheets
//     interleave),
//   each lies on the merged plane M (least squares on both) within the noise or within the merge
//     angle as seen from the other: |median residual of A - median residual of B| <=
//     max(2 tau, tan(2 deg) x the distance between their centroids along M),
//   and they are connected through points near M: the neighbour graph restricted to the points
//     of A, B and the free points within M's band (tau_M = max(tau, 3 sigma_M), sigma_M =
//     1.4826 MAD of the residuals of A and B about M) whose normals agree joins them (two tables
//     at the same height are not one plane; a wall around its windows is).
// Merged planes keep their band tau_M for the re-assignment, which then collects the wall's
// free points, and keep every connected part of at least the smallest primitive's size.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "fit/detect/primitive_detector.h"
#include "datasets/clouds/neighbour_graph.h"

namespace implicitfit {

struct SurfaceMergeContext {
  const std::vector<Eigen::Vector3d>& x;  // recentred points
  const std::vector<Eigen::Vector3d>& n;  // normals
  const NeighbourGraph& nb;
  double tau = 0.0;          // the distance band
  double cos_theta = 1.0;    // the normal band
  int min_points = 10;       // the smallest primitive
};

// Splits two-sheet planes; primitives and labels (index into primitives, -1 free) are updated
// together. Returns the number of planes split.
int SplitParallelSheets(const SurfaceMergeContext& c, std::vector<DetectedPrimitive>* primitives,
                        std::vector<int>* labels);

// Merges pieces of one plane. band (per primitive, output): the merged planes' tau_M, tau for
// the others; multi_part: 1 for merged planes. Returns the number of merges.
int MergeSameSurfaces(const SurfaceMergeContext& c, std::vector<DetectedPrimitive>* primitives,
                      std::vector<int>* labels, std::vector<double>* band,
                      std::vector<char>* multi_part);

}  // namespace implicitfit
