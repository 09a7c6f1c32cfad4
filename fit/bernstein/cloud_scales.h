// The scales of an oriented cloud that set the patch-mesh fit's defaults (docs/patch-mesh.md,
// "Adaptive refinement"): the sample spacing s (median distance of a point to its nearest
// neighbour) and the noise sigma along the normal (fit/detect/surface_noise.h: the mid-normal
// distance of neighbours, free of the curvature bias; that figure is the noise of a difference of
// two points, sqrt(2) sigma, so it is divided by sqrt(2)), the size (longest extent of the
// bounding box). Neighbours from a bucket grid of cell diagonal / sqrt(N)
// (fit/bernstein/point_hash_grid.h); every `stride`-th point is used for the medians.
#pragma once

#include <Eigen/Core>
#include <vector>

namespace implicitfit {

struct CloudScales {
  double spacing = 0.0;
  double noise = 0.0;
  double size = 0.0;
};

// At least 2 points spanning a finite box (std::invalid_argument otherwise).
CloudScales EstimateCloudScales(const std::vector<Eigen::Vector3d>& points,
                                const std::vector<Eigen::Vector3d>& normals, size_t stride = 1);

}  // namespace implicitfit
