// Oriented points on a model's zero set, with known truth (the `sample` command and the
// recovery tests). Works for every model kind, blends included, and draws uniformly by area:
//   1. mesh the zero set inside a box (SamplingBox: derived from the primitives' parameters, or
//      given) with datasets/meshing/model_mesher.h (80 cells along the longest side), draw a triangle
//      with probability proportional to its area and a uniform point in it,
//   2. project it onto f = 0 by Newton steps
//      x <- x - f(x) grad f(x) / |grad f(x)|^2 until |f| < 1e-12 (1 + |x|_inf) (or give up after
//      50); the points move by O(h^2 curvature) (h: the mesh cell), so the density stays uniform by
//      area up to that order (the former draw, uniform in the box then projected, followed the
//      catchment volume: on a half ball 52% of the points fell on the disk, 33% of the area),
//   3. keep it if f is smooth there (f(x +- h n) = +-h |grad f| within 10%, h = 1e-4 of the box
//      diagonal: this drops points that collapsed onto a cone's apex or a sharp crease), and if
//      it stays inside the box and the optional view cone (partial views: only the
//      points whose outward normal is within view_angle of view_dir, like a scanner sees them).
// Parts of the zero set thinner than a mesh cell may be missed.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "datasets/clouds/point_cloud.h"
#include "model/model.h"

namespace implicitfit {

struct SampleOptions {
  int count = 1000;               // points in the output (inliers + outliers)
  double noise = 0.0;             // sigma of the displacement along the normal
  double outlier_fraction = 0.0;  // in [0, 1)
  unsigned seed = 1;
  Eigen::Vector3d view_dir = Eigen::Vector3d::Zero();  // zero: no partial view
  double view_angle_deg = 180.0;                       // keep normals within this angle of view_dir
  bool has_box = false;  // use box_min/box_max instead of the model's box
  Eigen::Vector3d box_min = Eigen::Vector3d::Zero(), box_max = Eigen::Vector3d::Zero();
};

struct SampledCloud {
  PointCloud cloud;
  std::vector<bool> is_outlier;      // truth, one per point
  // Truth labels, one per point: the index (among the model's leaf nodes, in node order) of
  // the leaf whose zero set the point was drawn on, i.e. the leaf with the smallest |f| at the
  // projected point when that is below 1e-8 of the box diagonal; -1 for outliers and for
  // points on no leaf (a smooth blend's fillet).
  std::vector<int> primitive;
  std::vector<int> leaf_nodes;       // the node index (Model::nodes) of each leaf
  Eigen::Vector3d box_min, box_max;  // the box that was sampled
};

// Throws std::runtime_error when the zero set cannot be reached inside the box.
SampledCloud SampleModel(const Model& model, const SampleOptions& options);

// A box that holds the interesting part of the model's zero set (primitives: their extent,
// infinite ones a region around their point/apex of a few radii; Bernstein patches: their
// tetrahedron's bounding box grown by 5%; operators: union of the children's boxes).
void SamplingBox(const Model& model, Eigen::Vector3d* box_min, Eigen::Vector3d* box_max);

}  // namespace implicitfit
