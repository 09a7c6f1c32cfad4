// The cloud a Python call works on: the points of an (N, 3) array, and its normals as given
// (scaled to unit length) or, for normals=None, estimated and oriented as the command line does
// for a file without normals (datasets/normals/normal_estimation.h). Shared by fit, detect and
// reconstruct: read with the GIL, estimated without it.
#pragma once

#include <pybind11/pybind11.h>

#include <cstddef>
#include <string>

#include "datasets/clouds/point_cloud.h"

namespace implicitfit::python {

struct InputCloud {
  PointCloud cloud;
  std::string action;     // "given", or how the normals were estimated
  bool estimate = false;  // normals=None: EstimateNormalsIfMissing estimates them
};

// ValueError for a bad array or fewer than min_points points (python/arrays.h).
InputCloud ReadInputCloud(const pybind11::handle& points, const pybind11::handle& normals,
                          size_t min_points);
// Call without the GIL.
void EstimateNormalsIfMissing(InputCloud* in);

}  // namespace implicitfit::python
