// Detection the tests' way: a cloud's neighbourhoods (datasets/normals/neighbourhoods.h), then
// the detector (fit/detect/primitive_detector.h); and the kinds of a detection's primitives in
// its order (the detected side of fit/detect/segmentation_metrics.h's comparison).
#pragma once

#include <vector>

#include "datasets/clouds/point_cloud.h"
#include "datasets/normals/neighbourhoods.h"
#include "fit/detect/primitive_detector.h"

namespace testsupport {

inline implicitfit::DetectionResult DetectCloud(const implicitfit::PointCloud& cloud,
                                                const implicitfit::DetectionOptions& options = {}) {
  const implicitfit::Neighbourhoods nb = implicitfit::FindNeighbourhoods(cloud.points);
  return implicitfit::DetectPrimitives(cloud.points, cloud.normals, nb.indices, nb.spacing,
                                       options);
}

inline std::vector<implicitfit::NodeType> KindsOf(const implicitfit::DetectionResult& r) {
  std::vector<implicitfit::NodeType> kinds;
  for (const auto& p : r.primitives) kinds.push_back(p.kind);
  return kinds;
}

}  // namespace testsupport
