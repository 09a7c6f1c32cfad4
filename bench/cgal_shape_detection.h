// CGAL 5.5 Efficient RANSAC (Schnabel et al. 2007), the anchor of `implicitfit detect`, behind
// a plain interface so that only this bench translation unit includes CGAL (slow to compile).
#pragma once

#include <Eigen/Core>
#include <vector>

#include "model/model.h"

namespace implicitfit_bench {

struct CgalParameters {
  bool defaults = true;  // CGAL's own defaults (every field below ignored)
  double probability = 0.01;
  double min_points_fraction = 0.01;  // min_points = this * N
  double epsilon_fraction = 0.01;     // epsilon = this * bbox diagonal
  double cluster_epsilon_fraction = 0.01;
  double normal_threshold = 0.9;
  double max_seconds = 0.0;  // > 0: stop the detection after this long (CGAL's callback)
};

struct CgalDetection {
  std::vector<int> labels;                   // per point, -1 unassigned
  std::vector<implicitfit::NodeType> kinds;  // per shape
  double seconds = 0.0;
  bool stopped = false;  // hit max_seconds
};

CgalDetection CgalEfficientRansac(const std::vector<Eigen::Vector3d>& points,
                                  const std::vector<Eigen::Vector3d>& normals,
                                  const CgalParameters& p);

}  // namespace implicitfit_bench
