// Sharp edges and corners for a marching-cubes mesh of a zero set (extended marching cubes,
// Kobbelt, Botsch, Schwanecke & Seidel, "Feature sensitive surface extraction from volume data",
// SIGGRAPH 2001), using the model's f and grad f instead of a distance volume:
//   1. the triangles of one grid cell that share edges form a patch (a disk whose boundary loop
//      runs over the cell's faces). When the unit normals n_i = grad f / |grad f| at its
//      vertices p_i spread by more than the feature angle, the patch holds a crease or a corner:
//      the feature point x minimises the quadric error sum_i (n_i . (x - p_i))^2 (the tangent
//      planes' intersection), solved by SVD about the mass point m = mean p_i with singular
//      values below 0.1 of the largest dropped (a crease keeps rank 2, a corner rank 3):
//      x = m + V S^+ U^T (b - A m), A rows n_i^T, b_i = n_i . p_i;
//   2. x is kept only when it lies in the cell (grown by a margin) and on the surface to first
//      order (|f(x)| / |grad f(x)| <= max_distance cells); then the patch is replaced by the fan
//      of its boundary edges to x. The boundary edges and their orientation are unchanged, so a
//      watertight, consistently oriented mesh stays so, with the same Euler characteristic;
//   3. two fan triangles of neighbouring cells that share a boundary edge (a, b) are flipped to
//      share the edge between their feature points, (x1, a, x2) and (x2, b, x1), when neither
//      new triangle folds over (its normal agrees with the pair's): the crease becomes a chain of
//      mesh edges through the feature points instead of a band cut across it.
// Feature points' normals are the area-weighted mean of their triangles' normals (grad f jumps
// on a crease); unreferenced vertices (interior to a replaced patch) are removed.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "datasets/meshing/model_mesher.h"
#include "model/model.h"

namespace implicitfit {

struct SharpFeatureOptions {
  double feature_angle_deg = 30.0;  // normals spreading more than this mark a feature
  double cell_margin = 0.25;        // the feature point may leave its cell by this many cells
  double max_distance = 0.25;       // largest first-order distance of a feature point, cells
};

struct SharpFeatureStats {
  int feature_points = 0;   // patches replaced by fans
  int rejected = 0;         // feature patches left as they were (point outside or off surface)
  int flips = 0;            // crease edges made by flips
  double max_distance = 0;  // largest |f| / |grad f| at the feature points
};

// triangle_cells[t]: the grid cell (i, j, k) of mesh->triangles[t]; cell (i, j, k) spans
// origin + h [i, i+1] x [j, j+1] x [k, k+1]. mesh->normals must hold grad f / |grad f|.
SharpFeatureStats InsertSharpFeatures(const Model& model, const Eigen::Vector3d& origin, double h,
                                      const std::vector<Eigen::Vector3i>& triangle_cells,
                                      TriangleMesh* mesh, const SharpFeatureOptions& options = {});

}  // namespace implicitfit
