// The kinds of a detection's primitives, in its order (the detected side of
// fit/detect/segmentation_metrics.h's comparison).
#pragma once

#include <vector>

#include "fit/detect/primitive_detector.h"

namespace testsupport {

inline std::vector<implicitfit::NodeType> KindsOf(const implicitfit::DetectionResult& r) {
  std::vector<implicitfit::NodeType> kinds;
  for (const auto& p : r.primitives) kinds.push_back(p.kind);
  return kinds;
}

}  // namespace testsupport
