// The round leaves the random convex trees of the certificate tests share, by kind: 0 a plane
// of normal a at 0.3-0.8 from the origin, 1 a sphere about c of radius 0.6-1.1, 2 a cylinder
// through c along a of radius 0.5-0.9, 3 a cone of axis a, its apex 1.2 behind c, of half angle
// 0.3-0.8 rad; the sizes drawn with r01 from rng. -1 (nothing added) for another kind.
#pragma once

#include <random>

#include "model/model.h"

namespace testsupport {

inline int AddRandomRoundLeaf(int kind, const Eigen::Vector3d& c, const Eigen::Vector3d& a,
                              std::uniform_real_distribution<double>& r01, std::mt19937& rng,
                              implicitfit::Model* m) {
  using implicitfit::NodeType;
  switch (kind) {
    case 0:
      return m->AddPrimitive(NodeType::kPlane, {a.x(), a.y(), a.z(), 0.3 + 0.5 * r01(rng)});
    case 1:
      return m->AddPrimitive(NodeType::kSphere, {c.x(), c.y(), c.z(), 0.6 + 0.5 * r01(rng)});
    case 2:
      return m->AddPrimitive(NodeType::kCylinder,
                             {c.x(), c.y(), c.z(), a.x(), a.y(), a.z(), 0.5 + 0.4 * r01(rng)});
    case 3: {
      const Eigen::Vector3d apex = c - 1.2 * a;
      return m->AddPrimitive(NodeType::kCone, {apex.x(), apex.y(), apex.z(), a.x(), a.y(), a.z(),
                                               0.3 + 0.5 * r01(rng)});
    }
    default:
      return -1;
  }
}

}  // namespace testsupport
