// The capsule of end points p, q and radius r: a skeleton offset of one segment (the recovery
// tests' truth, their start and their Cramer-Rao residual).
#pragma once

#include "model/model.h"

namespace testsupport {

inline implicitfit::Model Capsule(const Eigen::Vector3d& p, const Eigen::Vector3d& q, double r) {
  implicitfit::Model m;
  m.AddSkeletonOffset(implicitfit::SkeletonKind::kSegments,
                      {p.x(), p.y(), p.z(), q.x(), q.y(), q.z()}, r);
  return m;
}

}  // namespace testsupport
