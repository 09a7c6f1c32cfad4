// Internal to datasets/: how every reader stores a normal read from a file. A finite,
// non-zero normal is normalised; a NaN, infinite or zero-length one is stored as a zero
// vector and its index listed in info->invalid_normals (ReadCloudFile re-estimates it).
#pragma once

#include <cmath>

#include "datasets/clouds/cloud_file_info.h"
#include "datasets/clouds/point_cloud.h"

namespace implicitfit {

inline void AddFileNormal(const Eigen::Vector3d& n, PointCloud* cloud, CloudFileInfo* info) {
  const double length = n.norm();
  if (!std::isfinite(length) || length == 0.0) {
    info->invalid_normals.push_back(cloud->normals.size());
    cloud->normals.push_back(Eigen::Vector3d::Zero());
  } else {
    cloud->normals.push_back(n / length);
  }
}

}  // namespace implicitfit
