// implicitfit.read_cloud, estimate_normals, check: clouds and certificates
// (datasets/normals/oriented_cloud.h, datasets/normals/normal_estimation.h,
// model/certificates/convexity_report.h) with NumPy arrays in and out.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <cmath>
#include <filesystem>
#include <string>

#include "datasets/normals/normal_estimation.h"
#include "datasets/normals/oriented_cloud.h"
#include "model/certificates/convexity_report.h"
#include "python/arrays.h"
#include "python/bindings.h"
#include "python/json_to_python.h"

namespace implicitfit::python {
namespace {

py::tuple ReadCloud(const std::filesystem::path& path, bool estimate) {
  PointCloud cloud;
  {
    py::gil_scoped_release release;
    cloud = ReadOrientedCloud(path.string(), nullptr, estimate);
  }
  py::object normals =
      cloud.has_normals() ? py::object(ArrayFromPoints(std::move(cloud.normals))) : py::none();
  return py::make_tuple(ArrayFromPoints(std::move(cloud.points)), normals);
}

py::array_t<double> EstimateNormals(const py::handle& points, const py::handle& viewpoint,
                                    int min_k, int max_k) {
  if (min_k < 3 || max_k < min_k)
    throw py::value_error("min_k, max_k: need 3 <= min_k <= max_k, got " + std::to_string(min_k) +
                          ", " + std::to_string(max_k));
  PointCloud cloud;
  cloud.points = PointsFromArray(points, "points", 3);
  NormalOptions options;
  options.reestimate = true;
  options.neighbourhood.min_k = min_k;
  options.neighbourhood.max_k = max_k;
  if (!viewpoint.is_none()) {
    const std::vector<double> v = viewpoint.cast<std::vector<double>>();
    if (v.size() != 3 || !std::isfinite(v[0]) || !std::isfinite(v[1]) || !std::isfinite(v[2]))
      throw py::value_error("viewpoint: expected 3 finite numbers");
    options.viewpoint = Eigen::Vector3d(v[0], v[1], v[2]);
  }
  {
    py::gil_scoped_release release;
    EnsureOrientedNormals(&cloud, options);
  }
  return ArrayFromPoints(std::move(cloud.normals));
}

}  // namespace

void BindClouds(py::module_& m) {
  m.def("read_cloud", &ReadCloud, py::arg("path"), py::arg("estimate") = false,
        "Reads .xyz/.pwn/.txt/.ply/.pcd: (points, normals or None), (N, 3) float64 arrays.\n"
        "The file's normals come as the command line fits them (re-oriented when their signs are\n"
        "inconsistent); estimate=True also estimates missing ones exactly as the command line\n"
        "does (toward the file's viewpoint when it has one). OSError when unreadable.");
  m.def("estimate_normals", &EstimateNormals, py::arg("points"), py::arg("viewpoint") = py::none(),
        py::arg("min_k") = 8, py::arg("max_k") = 30,
        "PCA normals over density-adaptive neighbourhoods (min_k..max_k neighbours), oriented\n"
        "toward viewpoint when given, else by minimum-spanning-tree propagation: (N, 3) array.");
  m.def(
      "check", [](const Model& model) { return ToPython(ModelConvexityJson(model)); },
      py::arg("model"),
      "Convexity certificate of every Bernstein patch, as one file's entry of `implicitfit check\n"
      "--json`: {\"convex\": bool, \"patches\": [{\"degree\", \"convex\", \"min_eigenvalue\"}]}.");
}

}  // namespace implicitfit::python
