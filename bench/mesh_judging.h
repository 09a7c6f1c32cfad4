// Figures of a reconstructed triangle mesh against a truth surface, and PCL's reconstructions,
// shared by the bench/ programs that compare implicitfit with PCL (bench only: PCL's surface
// module is linked here and nowhere else).
//   Chamfer distance: mean of the two directed mean distances, mesh -> truth at 50 000
//   area-uniform mesh points, truth -> mesh by exact point-triangle distance (nearest of the 16
//   triangles with the nearest centroids). Hausdorff distance: the largest of both. Normal
//   consistency: mean of n_mesh . n_truth at the mesh points (signed: 1 is perfect, orientation
//   included). Watertight: every edge in exactly two triangles (bad_edges counts the others).
// The truth is a TruthSurface: a distance (and unit outward normal) at any point, and points on
// it. ModelTruth: a generated model, first-order distance |f| / |grad f| and grad f / |grad f|;
// CloudTruth: a scan, distance to and normal of the nearest input point.
#pragma once

#include <pcl/PolygonMesh.h>

#include <Eigen/Core>
#include <functional>
#include <vector>

#include "datasets/meshing/model_mesher.h"
#include "model/model.h"

namespace bench {

using Vec = Eigen::Vector3d;

struct Figures {
  double chamfer = 0, hausdorff = 0, normal_consistency = 0, seconds = 0;
  double mesh_to_truth = 0, truth_to_mesh = 0;  // the two directed means of the Chamfer distance
  long bad_edges = 0;
  size_t triangles = 0;
};

struct TruthSurface {
  std::function<double(const Vec& x, Vec* unit_normal)> distance;
  std::vector<Vec> points;
};

TruthSurface ModelTruth(const implicitfit::Model& truth, std::vector<Vec> truth_points);
TruthSurface CloudTruth(const std::vector<Vec>& points, const std::vector<Vec>& normals);

// Figures with seconds = 0 (the caller times its reconstruction). An empty mesh gets infinite
// distances and every figure but triangles = 0 meaningless.
Figures JudgeMesh(const implicitfit::TriangleMesh& mesh, const TruthSurface& truth, unsigned seed);
// The same against a model and noise-free points on it (bench/solid_comparison's form).
Figures Judge(const implicitfit::TriangleMesh& mesh, const implicitfit::Model& truth,
              const std::vector<Vec>& truth_points, unsigned seed);

implicitfit::TriangleMesh FromPcl(const pcl::PolygonMesh& poly);
// pcl::Poisson at `depth` (other settings PCL's defaults) on an oriented cloud.
implicitfit::TriangleMesh PoissonMesh(const std::vector<Vec>& points,
                                      const std::vector<Vec>& normals, int depth);
// pcl::MarchingCubesHoppe (signed distance to the nearest point's tangent plane) on a
// resolution^3 grid over the cloud's box grown by `extend` of its size.
implicitfit::TriangleMesh HoppeMesh(const std::vector<Vec>& points, const std::vector<Vec>& normals,
                                    int resolution, float extend = 0.1f);

}  // namespace bench
