// CGAL 5.5's Poisson surface reconstruction (Kazhdan, Bolitho & Hoppe 2006, CGAL's implementation:
// poisson_surface_reconstruction_delaunay: an implicit function solved on a Delaunay refinement
// of the points, contoured by CGAL's surface mesher), behind an Eigen-only interface so that
// CGAL (header-only, slow to compile) stays in this translation unit.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "datasets/meshing/model_mesher.h"

namespace implicitfit_bench {

struct CgalPoissonResult {
  bool success = false;
  implicitfit::TriangleMesh mesh;  // normals: the faces' area-weighted mean
  double average_spacing = 0.0;    // CGAL's compute_average_spacing, 6 neighbours
  double seconds = 0.0;            // spacing + reconstruction
};

// Surface mesher criteria: sm_angle 20 deg (CGAL's default), sm_radius 1 and sm_distance 0.25
// average spacings (CGAL's defaults 30 and 0.375 give about 50 times fewer triangles than the
// other meshes of the bench: 1588 on the rounded box; these make the resolutions comparable).
CgalPoissonResult CgalPoisson(const std::vector<Eigen::Vector3d>& points,
                              const std::vector<Eigen::Vector3d>& normals);

}  // namespace implicitfit_bench
