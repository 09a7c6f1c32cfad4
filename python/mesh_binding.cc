// implicitfit.mesh: a triangle mesh of a model's zero set, as `implicitfit mesh MODEL.json`
// makes it (datasets/meshing/model_mesher.h: MeshModel, its default box), as NumPy arrays
// (V, F). The model is a Model or the model file as a dict (e.g. ReconstructResult.model). The
// GIL is released while meshing.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cstdint>
#include <optional>
#include <string>

#include "datasets/meshing/model_mesher.h"
#include "model/file/model_json.h"
#include "python/arrays.h"
#include "python/bindings.h"
#include "python/options.h"

namespace implicitfit::python {
namespace {

// A Model, or a model file's dict read with the model file's rules (ValueError when invalid).
Model ModelFrom(const py::handle& object) {
  if (py::isinstance<Model>(object)) return object.cast<Model>();
  if (!py::isinstance<py::dict>(object))
    throw py::type_error("model: expected a Model or a model file as a dict");
  const std::string text =
      py::module_::import("json").attr("dumps")(object).cast<std::string>();
  nlohmann::json document;
  try {
    document = nlohmann::json::parse(text);
  } catch (const nlohmann::json::parse_error& e) {
    throw py::value_error(std::string("model: ") + e.what());
  }
  return ModelFromJson(document);  // ModelFormatError -> ValueError (module.cc)
}

py::tuple Mesh(const py::handle& model_object, std::optional<double> cell) {
  const Model model = ModelFrom(model_object);
  MeshOptions options;
  if (cell) options.cell = PositiveFrom(*cell, "cell");
  MeshResult result;
  {
    py::gil_scoped_release release;
    result = MeshModel(model, options);  // std::invalid_argument -> ValueError
  }
  const std::vector<Eigen::Vector3i>& t = result.mesh.triangles;
  py::array_t<std::int64_t> faces({static_cast<py::ssize_t>(t.size()), py::ssize_t(3)});
  std::int64_t* f = faces.mutable_data();
  for (size_t i = 0; i < t.size(); ++i)
    for (int c = 0; c < 3; ++c) f[3 * i + c] = t[i][c];
  return py::make_tuple(ArrayFromPoints(std::move(result.mesh.vertices)), faces);
}

}  // namespace

void BindMesh(py::module_& m) {
  m.def("mesh", &Mesh, py::arg("model"), py::arg("cell") = py::none(),
        "A triangle mesh of the model's zero set, as `implicitfit mesh MODEL.json`: (V, F),\n"
        "V (n, 3) float64 vertices, F (m, 3) int64 indices into V, counter-clockwise seen from\n"
        "outside. model: a Model or the model file as a dict. cell: the grid spacing (None:\n"
        "the longest side of the box / 100, or half the finest leaf of a patch mesh with creases,\n"
        "as `mesh`); the box is the model's proven bounds when its\n"
        "file states them (a verified solid), else the sampling box of `sample`.");
}

}  // namespace implicitfit::python
