#include "python/input_cloud.h"

#include "datasets/normals/normal_estimation.h"
#include "python/arrays.h"

namespace implicitfit::python {

InputCloud ReadInputCloud(const py::handle& points, const py::handle& normals,
                          size_t min_points) {
  InputCloud in;
  in.cloud.points = PointsFromArray(points, "points", min_points);
  if (normals.is_none()) {
    in.estimate = true;
  } else {
    in.cloud.normals = NormalsFromArray(normals, in.cloud.size());
    in.action = "given";
  }
  return in;
}

void EstimateNormalsIfMissing(InputCloud* in) {
  if (in->estimate) in->action = EnsureOrientedNormals(&in->cloud, NormalOptions{}).action;
}

}  // namespace implicitfit::python
