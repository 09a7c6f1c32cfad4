// A point cloud, optionally with one normal per point. double in memory (the fit works in
// double); big clouds are stored as float only in files.
#pragma once

#include <Eigen/Core>
#include <vector>

namespace implicitfit {

struct PointCloud {
  std::vector<Eigen::Vector3d> points;
  std::vector<Eigen::Vector3d> normals;  // empty, or one per point

  bool has_normals() const { return !normals.empty(); }
  size_t size() const { return points.size(); }
};

}  // namespace implicitfit
