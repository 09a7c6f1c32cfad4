// The box |x_a| <= half[a] about the origin as the intersection of its six face planes (outward
// normals -x, +x, -y, +y, -z, +z in that order, offsets half[a]), with the operator's delta,
// epsilon and order (0: sharp).
#pragma once

#include <vector>

#include "model/model.h"

namespace testsupport {

inline implicitfit::Model AxisBox(const Eigen::Vector3d& half, double delta, double epsilon,
                                  int order) {
  using implicitfit::NodeType;
  implicitfit::Model m;
  std::vector<int> faces;
  for (int a = 0; a < 3; ++a)
    for (int s : {-1, 1}) {
      Eigen::Vector3d n = Eigen::Vector3d::Zero();
      n[a] = s;
      faces.push_back(m.AddPrimitive(NodeType::kPlane, {n.x(), n.y(), n.z(), half[a]}));
    }
  m.SetRoot(m.AddOperator(NodeType::kIntersection, faces, delta, epsilon, order));
  return m;
}

}  // namespace testsupport
