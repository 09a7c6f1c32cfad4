#include "bench/cgal_poisson.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/compute_average_spacing.h>
#include <CGAL/poisson_surface_reconstruction.h>
#include <CGAL/property_map.h>

#include <chrono>
#include <utility>

namespace implicitfit_bench {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Pwn = std::pair<Kernel::Point_3, Kernel::Vector_3>;
using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;

CgalPoissonResult CgalPoisson(const std::vector<Eigen::Vector3d>& points,
                              const std::vector<Eigen::Vector3d>& normals) {
  CgalPoissonResult result;
  std::vector<Pwn> pwn;
  pwn.reserve(points.size());
  for (size_t i = 0; i < points.size(); ++i)
    pwn.emplace_back(Kernel::Point_3(points[i][0], points[i][1], points[i][2]),
                     Kernel::Vector_3(normals[i][0], normals[i][1], normals[i][2]));
  const auto start = std::chrono::steady_clock::now();
  result.average_spacing = CGAL::compute_average_spacing<CGAL::Sequential_tag>(
      pwn, 6, CGAL::parameters::point_map(CGAL::First_of_pair_property_map<Pwn>()));
  Mesh mesh;
  result.success = CGAL::poisson_surface_reconstruction_delaunay(
      pwn.begin(), pwn.end(), CGAL::First_of_pair_property_map<Pwn>(),
      CGAL::Second_of_pair_property_map<Pwn>(), mesh, result.average_spacing, 20.0, 1.0, 0.25);
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (!result.success) return result;
  std::vector<int> index(mesh.number_of_vertices() + mesh.number_of_removed_vertices(), -1);
  for (Mesh::Vertex_index v : mesh.vertices()) {
    const Kernel::Point_3& p = mesh.point(v);
    index[v] = static_cast<int>(result.mesh.vertices.size());
    result.mesh.vertices.emplace_back(p.x(), p.y(), p.z());
  }
  result.mesh.normals.assign(result.mesh.vertices.size(), Eigen::Vector3d::Zero());
  for (Mesh::Face_index f : mesh.faces()) {
    std::vector<int> ids;
    for (Mesh::Vertex_index v : CGAL::vertices_around_face(mesh.halfedge(f), mesh))
      ids.push_back(index[v]);
    for (size_t k = 1; k + 1 < ids.size(); ++k) {
      result.mesh.triangles.emplace_back(ids[0], ids[k], ids[k + 1]);
      const Eigen::Vector3d& a = result.mesh.vertices[ids[0]];
      const Eigen::Vector3d n =
          (result.mesh.vertices[ids[k]] - a).cross(result.mesh.vertices[ids[k + 1]] - a);
      for (int i : {ids[0], ids[k], ids[k + 1]}) result.mesh.normals[i] += n;
    }
  }
  for (Eigen::Vector3d& n : result.mesh.normals)
    n = n.norm() > 0 ? Eigen::Vector3d(n.normalized()) : Eigen::Vector3d::UnitZ();
  return result;
}

}  // namespace implicitfit_bench
