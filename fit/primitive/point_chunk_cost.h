// The base of the residual blocks that stand for a chunk of points of a primitive fit
// (fit/primitive/compressed_distance_cost.h, and the per-point reference form of the tests,
// fit/primitive/batched_distance_cost.h): the points, the chunk's indices into them, and the
// primitive's parameter blocks (its named fields in flat order, e.g. cylinder: point 3, axis 3,
// radius 1, so manifolds and bounds can be set per field).
#pragma once

#include <ceres/ceres.h>

#include <cstdint>
#include <utility>
#include <vector>

namespace implicitfit {

// What the point-chunk costs share: the points (xyz, 3 doubles per point, owned by the caller
// and alive while the cost is used), the chunk's indices into them, and the parameter blocks
// (the primitive's fields, block_sizes summing to kP) with their offsets in the flat layout.
class PointChunkCost : public ceres::CostFunction {
 protected:
  PointChunkCost(const double* xyz, std::vector<int> indices, const std::vector<int>& block_sizes,
                 int num_residuals)
      : xyz_(xyz), indices_(std::move(indices)) {
    int offset = 0;
    for (int size : block_sizes) {
      mutable_parameter_block_sizes()->push_back(size);
      offsets_.push_back(offset);
      offset += size;
    }
    set_num_residuals(num_residuals < 0 ? static_cast<int>(indices_.size()) : num_residuals);
  }
  // The blocks' values in the flat layout.
  void Gather(double const* const* parameters, double* p) const {
    const std::vector<int32_t>& sizes = parameter_block_sizes();
    for (size_t b = 0; b < sizes.size(); ++b)
      for (int j = 0; j < sizes[b]; ++j) p[offsets_[b] + j] = parameters[b][j];
  }

  const double* xyz_;
  std::vector<int> indices_;
  std::vector<int> offsets_;
};

}  // namespace implicitfit
