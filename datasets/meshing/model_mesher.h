// A triangle mesh of a model's zero set {x : f(x) = 0}, for any model tree (it only calls
// Model::Value and Model::Gradient, so every node kind meshes).
//   1. f is sampled on a regular grid of cell h over a box (default: the model's bounds when its
//      file states them (a verified solid, model/model.h ModelClaims), else SamplingBox of
//      datasets/generators/model_sampler.h; enlarged by 10% of its size and two cells on every
//      side; a Bernstein mesh root: its grid box, DefaultMeshBox);
//   2. VTK's vtkFlyingEdges3D contours the grid at 0: one vertex per grid edge whose ends
//      differ in sign, triangles from the marching-cubes case table (shared vertices, so a
//      surface that closes inside the box gives a closed, edge-manifold mesh);
//   3. every vertex lies on a grid edge [a, b] with f(a) < 0 <= f(b): it is moved to the root of
//      f on that edge by the Illinois (modified regula falsi) method, which keeps it bracketed,
//      so |f(vertex)| ends at the evaluation's rounding level for any continuous f (the linear
//      interpolation of step 2 is only first-order accurate);
//   3b. a vertex whose |f| stays above kJumpFraction h after step 3 marks a jump of f (a sign
//      change without a zero: the signed distance to an open bspline_surface beyond its
//      boundary), not a surface: the triangles touching it are dropped (drop_jumps);
//   4. vertex normals are grad f / |grad f| (outward, docs/design.md sign); where the gradient is
//      zero or not finite, the mean of the adjacent triangles' normals.
// Grid values that are NaN count as outside (+h); exact zeros are nudged to +tiny so that no
// vertex sits on a grid node. Surfaces leaving the box end open at its faces.
//   5. sharp edges and corners (sharp_features, on by default): marching cubes alone cuts a
//      crease by a band about one cell wide. Each cell's patch whose grad f normals spread by
//      more than feature_angle_deg is replaced by a fan to the intersection of its vertices'
//      tangent planes, and fans of neighbouring cells are flipped to share the crease edge
//      (extended marching cubes, datasets/meshing/sharp_features.h). This keeps the watertight, oriented
//      topology of step 2 (the patches' boundary edges are untouched). Chosen over dual
//      contouring (its meshes need not be manifold where a cell holds two sheets) and over
//      CGAL's Mesh_3 (its sharp features must be given as polylines, which a model does not
//      list).
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <functional>
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

// Step 3b: |f| at a refined vertex above this fraction of the cell marks a jump.
constexpr double kJumpFraction = 0.25;

struct MeshOptions {
  bool has_box = false;  // use box_min/box_max instead of the default box
  Eigen::Vector3d box_min = Eigen::Vector3d::Zero(), box_max = Eigen::Vector3d::Zero();
  double cell = 0.0;                 // grid spacing; 0: DefaultMeshCell (default_mesh_cell.h)
  int num_threads = 0;               // for the grid values; 0 = hardware concurrency
  long max_grid_points = 64L << 20;  // refuse finer grids (memory: 8 bytes a point)
  bool sharp_features = true;        // step 5
  bool drop_jumps = true;            // step 3b (header)
  double feature_angle_deg = 30.0;   // step 5: normals spreading more mark a crease or corner
  // Called after each step with what it made ("grid 120x80x60 sampled", ...); empty: nothing
  // (jobs/mesh_job.cc turns it into progress on stderr).
  std::function<void(const std::string&)> on_step;
};

struct MeshResult {
  TriangleMesh mesh;
  Eigen::Vector3d box_min, box_max;   // the box that was gridded
  double cell = 0.0;                  // the grid spacing used
  double max_abs_value = 0.0;         // max |f| over the refined (grid-edge) vertices
  int jump_triangles = 0;             // step 3b: triangles dropped at jumps of f
  int feature_points = 0;             // step 5: vertices placed on creases and corners
  int feature_flips = 0;              // step 5: crease edges made by flips
  double max_feature_distance = 0.0;  // step 5: largest |f| / |grad f| at a feature point
};

// Throws std::invalid_argument for an invalid box or cell (or a grid above max_grid_points).
MeshResult MeshModel(const Model& model, const MeshOptions& options = {});

// The default box of `mesh`: the model's bounds (ModelClaims) or else SamplingBox, enlarged by
// 10% of its size on every side; a model whose root is a Bernstein mesh (without bounds): its
// grid box, not enlarged (outside it f is an extrapolation).
void DefaultMeshBox(const Model& model, Eigen::Vector3d* box_min, Eigen::Vector3d* box_max);

// Writes the mesh as binary little-endian PLY: vertex x y z nx ny nz (double), face
// vertex_indices (uchar count, int indices). Atomic (datasets/io/atomic_file.h).
void WriteMeshPlyFile(const TriangleMesh& mesh, const std::string& path);

}  // namespace implicitfit
