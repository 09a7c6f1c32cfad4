// implicitfit.Model: a model tree (model/model.h) with its JSON form (model/file/model_json.h),
// files (datasets/io/model_file.h) and evaluation on NumPy arrays.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "datasets/io/model_file.h"
#include "model/model.h"
#include "model/file/model_json.h"
#include "python/arrays.h"
#include "python/bindings.h"

namespace implicitfit::python {
namespace {

Model FromJson(const std::string& text) {
  nlohmann::json document;
  try {
    document = nlohmann::json::parse(text);
  } catch (const nlohmann::json::parse_error& e) {
    std::string what = e.what();
    const size_t at = what.find("] ");
    throw py::value_error("invalid JSON: " +
                          (at == std::string::npos ? what : what.substr(at + 2)));
  }
  return ModelFromJson(document);
}

// {"center": array([x, y, z]), "radius": r} for a one-node model; nodes below the root (or named
// ones) are prefixed by their label: "children[1].radius", "cap.axis".
py::dict Parameters(const Model& model) {
  py::dict out;
  for (size_t n = 0; n < model.nodes().size(); ++n) {
    const ModelNode& node = model.nodes()[n];
    std::string label = model.NodeLabel(static_cast<int>(n));
    if (label == "root")
      label.clear();
    else if (label.rfind("root.", 0) == 0)
      label = label.substr(5);
    const double* p = model.parameters().data() + node.first_parameter;
    for (const ParameterField& field : ParameterFieldsOf(node)) {
      const std::string key = label.empty() ? field.name : label + "." + field.name;
      if (field.size == 1)
        out[py::str(key)] = py::float_(*p);
      else
        out[py::str(key)] = py::array_t<double>(field.size, p);  // a copy: the dict is a snapshot
      p += field.size;
    }
  }
  return out;
}

std::string Repr(const Model& model) {
  std::string root = ModelToJson(model)["root"].dump();
  if (root.size() > 400) root = root.substr(0, 400) + " ...";
  return "implicitfit.Model(" + root + ")";
}

}  // namespace

void BindModel(py::module_& m) {
  py::class_<Model>(m, "Model",
                    "An implicit surface model: f(x) < 0 inside, f > 0 outside, grad f outward.\n"
                    "Create it with Model.from_json / Model.load, or get it from fit().")
      .def_static("from_json", &FromJson, py::arg("text"),
                  "The model of a model-file JSON text (docs/model-file.md); ValueError when "
                  "invalid, naming the offending field.")
      .def_static(
          "load", [](const std::filesystem::path& path) { return ReadModelFile(path.string()); },
          py::arg("path"),
          "Reads a model file; OSError with the command line's message when unreadable "
          "or invalid.")
      .def(
          "to_json", [](const Model& model, int indent) { return ModelToJson(model).dump(indent); },
          py::arg("indent") = 2, "The model-file JSON text (round-trip precision).")
      .def(
          "save",
          [](const Model& model, const std::filesystem::path& path) {
            WriteModelFile(model, path.string());
          },
          py::arg("path"), "Writes the model file atomically (as `implicitfit fit --out`).")
      .def(
          "evaluate",
          [](const Model& model, const py::handle& points) {
            const py::array rows = CheckedRows(points, "points");
            py::array_t<double> f(rows.shape(0));
            double* out = f.mutable_data();
            {
              py::gil_scoped_release release;
              ForEachRow(rows,
                         [&](py::ssize_t i, const Eigen::Vector3d& x) { out[i] = model.Value(x); });
            }
            return f;
          },
          py::arg("points"),
          "f at each row of an (N, 3) array: an (N,) array (signed distance for primitives).")
      .def(
          "gradient",
          [](const Model& model, const py::handle& points) {
            const py::array rows = CheckedRows(points, "points");
            py::array_t<double> g({rows.shape(0), py::ssize_t(3)});
            double* out = g.mutable_data();
            {
              py::gil_scoped_release release;
              ForEachRow(rows, [&](py::ssize_t i, const Eigen::Vector3d& x) {
                Eigen::Map<Eigen::Vector3d>(out + 3 * i) = model.Gradient(x);
              });
            }
            return g;
          },
          py::arg("points"), "grad f at each row of an (N, 3) array: an (N, 3) array.")
      .def_property_readonly(
          "parameters", &Parameters,
          "The parameters by field: {\"axis\": array([...]), \"radius\": r, ...}.")
      .def_property_readonly(
          "kind",
          [](const Model& model) {
            return std::string(NodeTypeName(model.nodes()[model.root()].type));
          },
          "The root node's type: \"sphere\", \"union\", \"bernstein_patch\", ...")
      .def("__repr__", &Repr);
}

}  // namespace implicitfit::python
