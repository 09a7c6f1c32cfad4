// A triangle mesh of a model's zero set {x : f(x) = 0}, for any model tree (it only calls
// Model::Value and Model::Gradient, so every node kind meshes).
//   1. f is sampled on a regular grid of cell h over a box (default: SamplingBox of
//      datasets/model_sampler.h enlarged by 10% of its size and two cells on every side);
//   2. VTK's vtkFlyingEdges3D contours the grid at 0: one vertex per grid edge whose ends
//      differ in sign, triangles from the marching-cubes case table (shared vertices, so a
//      surface that closes inside the box gives a closed, edge-manifold mesh);
//   3. every vertex lies on a grid edge [a, b] with f(a) < 0 <= f(b): it is moved to the root of
//      f on that edge by the Illinois (modified regula falsi) method, which keeps it bracketed,
//      so |f(vertex)| ends at the evaluation's rounding level for any continuous f (the linear
//      interpolation of step 2 is only first-order accurate);
//   4. vertex normals are grad f / |grad f| (outward, DESIGN.md sign); where the gradient is
//      zero or not finite, the mean of the adjacent triangles' normals.
// Grid values that are NaN count as outside (+h); exact zeros are nudged to +tiny so that no
// vertex sits on a grid node. Surfaces leaving the box end open at its faces. Sharp edges are
// cut by a band of about one cell (marching cubes does not place vertices on creases).
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <string>
#include <vector>

#include "model/model.h"

namespace implicitfit {

struct TriangleMesh {
  std::vector<Eigen::Vector3d> vertices;
  std::vector<Eigen::Vector3d> normals;  // one unit normal per vertex
  std::vector<Eigen::Vector3i>
      triangles;  // indices into vertices, counter-clockwise seen from outside
};

struct MeshOptions {
  bool has_box = false;  // use box_min/box_max instead of the default box
  Eigen::Vector3d box_min = Eigen::Vector3d::Zero(), box_max = Eigen::Vector3d::Zero();
  double cell = 0.0;                 // grid spacing; 0: longest box side / 100
  int num_threads = 0;               // for the grid values; 0 = hardware concurrency
  long max_grid_points = 64L << 20;  // refuse finer grids (memory: 8 bytes a point)
};

struct MeshResult {
  TriangleMesh mesh;
  Eigen::Vector3d box_min, box_max;  // the box that was gridded
  double cell = 0.0;                 // the grid spacing used
  double max_abs_value = 0.0;        // max |f| over the refined vertices
};

// Throws std::invalid_argument for an invalid box or cell (or a grid above max_grid_points).
MeshResult MeshModel(const Model& model, const MeshOptions& options = {});

// The default box of `mesh`: SamplingBox enlarged by 10% of its size on every side.
void DefaultMeshBox(const Model& model, Eigen::Vector3d* box_min, Eigen::Vector3d* box_max);

// Writes the mesh as binary little-endian PLY: vertex x y z nx ny nz (double), face
// vertex_indices (uchar count, int indices). Atomic (datasets/atomic_file.h).
void WriteMeshPlyFile(const TriangleMesh& mesh, const std::string& path);

}  // namespace implicitfit
