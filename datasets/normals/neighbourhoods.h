// k-nearest-neighbour neighbourhoods of a cloud (FLANN k-d tree, exact search), with k chosen
// from the local density for normal estimation:
//   s = median over the points of the distance to their 6th nearest neighbour (the sampling
//       spacing); each point's neighbourhood is every neighbour within radius_factor * s,
//       but at least min_k and at most max_k of them (nearest first).
// On an evenly sampled surface, radius 2s holds about 4 x 6 = 24 neighbours; sparse regions
// fall back to min_k, dense ones are capped at max_k. The search runs on coordinates recentred
// at the centroid, so far-off clouds (UTM, ~1e6) lose no precision. Exact duplicates are
// searched once (a k-d tree cannot split equal points: 80 000 copies of a point made every
// query scan them all); each copy then gets its copies first (distance 0), then the copies of
// the unique neighbours, as a search over all points would. The queries run in blocks on all
// cores, each writing its points' rows of the graph in place (datasets/clouds/neighbour_graph.h):
// the search holds the graph, the k-d tree and one block of results, about 200 bytes a point
// at max_k = 30. The result does not depend on the thread count.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "datasets/clouds/neighbour_graph.h"

namespace implicitfit {

struct NeighbourhoodOptions {
  int min_k = 8;               // never fewer neighbours than this (when the cloud has them)
  int max_k = 30;              // never more than this
  double radius_factor = 2.0;  // radius in units of the median 6th-neighbour distance
  int num_threads = 0;         // 0: every core
};

struct Neighbourhoods {
  NeighbourGraph indices;  // per point, its neighbours (itself excluded), nearest first
  double spacing = 0.0;  // s, the median 6th-neighbour distance
  double radius = 0.0;   // radius_factor * s
  size_t duplicates = 0;  // points equal to an earlier one (searched once: near-linear time)
};

// Throws std::invalid_argument when the cloud has fewer than 2 points.
Neighbourhoods FindNeighbourhoods(const std::vector<Eigen::Vector3d>& points,
                                  const NeighbourhoodOptions& options = {});

}  // namespace implicitfit
