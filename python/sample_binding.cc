// implicitfit.sample: the sample job (implicitfit/sample.h, as `implicitfit sample`): oriented
// points on a model's zero set with noise, outliers, a partial view and the truth, as NumPy
// arrays. The GIL is released while sampling.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cmath>
#include <string>

#include "implicitfit/sample.h"
#include "python/arrays.h"
#include "python/bindings.h"
#include "python/json_to_python.h"
#include "python/pair_result.h"

namespace implicitfit::python {
namespace {

// What `sample` returns; iterating gives (points, normals), as when `sample` returned that
// tuple.
struct SampleResult {
  py::object points, normals, outliers, labels, truth_kinds, report;
  size_t count = 0, outlier_count = 0;

  py::tuple AsTuple() const { return py::make_tuple(points, normals); }
  std::string Repr() const {
    return "SampleResult(points=" + std::to_string(count) +
           ", outliers=" + std::to_string(outlier_count) +
           ", truth_kinds=" + py::repr(truth_kinds).cast<std::string>() + ")";
  }
};

SampleResult Sample(const Model& model, long long count, double noise, double outliers,
                    long long seed, const py::handle& view, double view_angle) {
  if (count < 1 || count > 1000000000LL) throw py::value_error("count: must be in [1, 1e9]");
  if (seed < 0 || seed > 0xffffffffLL) throw py::value_error("seed: must be in [0, 2^32 - 1]");
  SampleJobOptions options;
  SampleOptions& o = options.sample;
  o.count = static_cast<int>(count);
  o.noise = noise;
  o.outlier_fraction = outliers;
  o.seed = static_cast<unsigned>(seed);
  o.view_angle_deg = view_angle;
  if (!view.is_none()) {
    const std::vector<double> v = view.cast<std::vector<double>>();
    if (v.size() != 3) throw py::value_error("view: expected 3 numbers");
    o.view_dir = Eigen::Vector3d(v[0], v[1], v[2]);
  }
  std::string error;
  if (!options.IsValid(&error)) throw py::value_error(error);
  SampleJobResult job;
  {
    py::gil_scoped_release release;
    job = SampleModelJob(model, options);
  }
  if (!job.success) throw std::runtime_error(job.message);  // -> RuntimeError
  const nlohmann::json report = job.ToJson();
  SampleResult out;
  out.count = job.sampled.cloud.size();
  out.outlier_count = report["outliers"].get<size_t>();
  py::array_t<bool> flags(static_cast<py::ssize_t>(job.sampled.is_outlier.size()));
  for (size_t i = 0; i < job.sampled.is_outlier.size(); ++i)
    flags.mutable_data()[i] = job.sampled.is_outlier[i];
  out.outliers = flags;
  out.labels = ArrayFromIndices(job.sampled.primitive);
  py::list kinds;
  for (NodeType k : job.truth_kinds) kinds.append(NodeTypeName(k));
  out.truth_kinds = job.truth_kinds.empty() ? py::object(py::none()) : py::object(kinds);
  out.report = ToPython(report);
  out.points = ArrayFromPoints(std::move(job.sampled.cloud.points));
  out.normals = ArrayFromPoints(std::move(job.sampled.cloud.normals));
  return out;
}

}  // namespace

void BindSample(py::module_& m) {
  py::class_<SampleResult> result(
      m, "SampleResult",
      "The result of sample(): points and normals ((N, 3) float64), outliers ((N,) bool), labels\n"
      "((N,) int64: the leaf drawn on, -1 outliers and blends), truth_kinds (one kind per leaf,\n"
      "or None), report (dict). Unpacks as (points, normals): `points, normals = sample(...)`.");
  result.def_readonly("points", &SampleResult::points)
      .def_readonly("normals", &SampleResult::normals, "Unit normals, grad f at the drawn point")
      .def_readonly("outliers", &SampleResult::outliers, "True for the uniform outliers")
      .def_readonly("labels", &SampleResult::labels,
                    "The leaf primitive (in node order) of each point, -1 for outliers and for\n"
                    "points on no leaf (a blend); `sample --truth` writes these")
      .def_readonly("truth_kinds", &SampleResult::truth_kinds,
                    "The kind of each leaf when every leaf drawn on is a plane, sphere, cylinder,\n"
                    "cone or torus (what detect is scored against), else None")
      .def_readonly("report", &SampleResult::report,
                    "The job's report (points, outliers, labelled, truth_kinds, box, settings)")
      .def("__repr__", &SampleResult::Repr);
  UnpacksAsPair(result, "SampleResult unpacks as (points, normals)");
  m.def("sample", &Sample, py::arg("model"), py::arg("count"), py::arg("noise") = 0.0,
        py::arg("outliers") = 0.0, py::arg("seed") = 0, py::arg("view") = py::none(),
        py::arg("view_angle") = 180.0,
        "Oriented points on the model's zero set, as `implicitfit sample` (implicitfit/sample.h).\n"
        "noise: sigma along the normal; outliers: fraction replaced by uniform points in the\n"
        "box; view, view_angle: a partial view (normals within view_angle degrees of view).\n"
        "Returns a SampleResult (points, normals, outliers, labels, truth_kinds, report;\n"
        "unpacks as (points, normals)). ValueError for invalid options, RuntimeError when the\n"
        "zero set cannot be reached.");
}

}  // namespace implicitfit::python
