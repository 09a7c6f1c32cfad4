// Generated multi-primitive scenes with exact per-point labels (detection tests and bench/).
//
// The scene: a ground plane z = 0 over [0, 4] x [0, 3] (`ground_points` points) and five
// objects floating above it, one per cell of a 3 x 2 grid (1.33 x 1.5 each, one cell left
// empty), in a random order of cells: a sphere cap (r in [0.3, 0.45], its lower part cut off),
// a cylinder (r in [0.18, 0.3], random axis, clipped by a 0.9 cube), a cone (half angle in
// [20, 35] deg, axis down, cut 0.15..0.7 below the apex), a torus (R in [0.28, 0.38], r in
// [0.08, 0.12], random axis) and a tilted square plane patch (normal within 45 deg of z), each
// with `object_points` points (datasets/generators/model_sampler.h: outward normals). Then every point
// moves along its normal by N(0, noise^2) (noise in the objects' unit of size: 1), and a
// fraction `outliers` of the total is added as points uniform in the scene box
// [0, 4] x [0, 3] x [0, 1.6] with random normals (label -1).
// polyhedron: instead, the 20 faces of a regular icosahedron of circumradius 1, each face
// `object_points` points uniform in the triangle (normals outward), same noise and outliers.
#pragma once

#include <vector>

#include "datasets/clouds/point_cloud.h"
#include "model/model.h"

namespace implicitfit {

struct GeneratedSceneOptions {
  unsigned seed = 1;
  int ground_points = 4000;
  int object_points = 1000;
  double noise = 0.005;
  double outliers = 0.1;     // fraction of the output points
  bool planes_only = false;  // every object a tilted plane patch (a plane-only scene)
};

struct GeneratedScene {
  PointCloud cloud;
  std::vector<int> labels;      // per point: index into models, -1 outlier
  std::vector<Model> models;    // one primitive each
  std::vector<NodeType> kinds;  // their kinds
};

GeneratedScene GenerateScene(const GeneratedSceneOptions& options);
GeneratedScene GenerateIcosahedron(const GeneratedSceneOptions& options);

}  // namespace implicitfit
