// Robust starting models for the kinds `fit --model` fits through the tree fitter
// (fit/tree/tree_fitter.h) instead of the primitive fitter: each start reuses the sample-consensus
// primitive fitter (fit/primitive/primitive_fitter.h) on a related primitive, so outliers do not move it.
//   paraboloid  the osculating sphere: a robust sphere fit (centre c, radius R), vertex where the
//               ray from c through the inliers' centroid meets the sphere, axis along that ray,
//               kappa = 1/R; with the normals pointing to c (concave) axis and kappa flip sign.
//   capsule     a robust cylinder fit (axis line, radius r); the segment spans the projections
//               of the cylinder's inliers on the axis (the caps' points are not its inliers).
//               The model is a skeleton_offset with one segment.
//   box         needs normals. A robust plane fit gives the first face normal e1; a second one
//               on the points whose normals are within 73 degrees of perpendicular to e1 gives
//               e2 (made orthogonal), e3 = e1 x e2. Per axis, the faces are the medians of
//               p . e_i over the points whose normal is within 26 degrees of +e_i, of -e_i.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "model/model.h"

namespace implicitfit {

struct ShapeStart {
  bool success = false;
  std::string message;  // why there is no start
  Model model;          // the start (one node)
};

// True for "paraboloid", "capsule", "box".
bool IsShapeStartKind(const std::string& kind);

ShapeStart RobustShapeStart(const std::string& kind, const std::vector<Eigen::Vector3d>& points,
                            const std::vector<Eigen::Vector3d>& normals, unsigned seed);

}  // namespace implicitfit
