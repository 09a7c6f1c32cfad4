#include "datasets/meshing/mesh_file.h"

#include <fstream>
#include <sstream>

#include "datasets/io/io_error.h"
#include "datasets/io/text_file.h"
#ifdef IMPLICITFIT_HAVE_PCL
#include <pcl/PolygonMesh.h>
#include <pcl/console/print.h>
#include <pcl/io/ply_io.h>

#include "datasets/clouds/cloud_file_info.h"
#include "datasets/clouds/ply_reader.h"
#endif

namespace implicitfit {

bool PlyHasFaces(const std::string& path) {
  const std::string bytes = ReadTextFile(path);
  std::istringstream in(bytes.substr(0, bytes.find("end_header")));
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream words(line);
    std::string keyword, element;
    long long count = 0;
    if (words >> keyword >> element >> count && keyword == "element" && element == "face")
      return count > 0;
  }
  return false;
}

TriangleMesh ReadMeshPlyFile(const std::string& path) {
#ifdef IMPLICITFIT_HAVE_PCL
  CloudFileInfo info;
  const PointCloud vertices = ReadPlyFile(path, &info);  // validates the header and the data
  pcl::console::setVerbosityLevel(pcl::console::L_ALWAYS);
  pcl::PolygonMesh poly;
  pcl::PLYReader reader;
  if (reader.read(path, poly) < 0) throw FileError(path, "malformed PLY faces (PCL's reader failed)");
  TriangleMesh mesh;
  mesh.vertices = vertices.points;
  if (vertices.has_normals() && info.invalid_normals.empty()) mesh.normals = vertices.normals;
  const size_t n = mesh.vertices.size();
  for (const pcl::Vertices& face : poly.polygons) {
    for (std::uint32_t v : face.vertices)
      if (v >= n)
        throw FileError(path, "a face indexes vertex " + std::to_string(v) + " of " +
                                  std::to_string(n));
    for (size_t k = 1; k + 1 < face.vertices.size(); ++k)
      mesh.triangles.emplace_back(face.vertices[0], face.vertices[k], face.vertices[k + 1]);
  }
  if (mesh.triangles.empty()) throw FileError(path, "no faces with three or more vertices");
  return mesh;
#else
  throw FileError(path, "PLY meshes need a build with PCL");
#endif
}

}  // namespace implicitfit
