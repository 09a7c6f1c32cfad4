// implicitfit.detect: every primitive of a cloud, as `implicitfit detect CLOUD` finds them
// (implicitfit/detect.h: DetectCloud), on NumPy arrays. The GIL is released for the normals and the
// detection. The result is a DetectResult: primitives (DetectedPrimitive: the scene file's model
// node as a dict, kind, indices of its points, rms_distance), labels per point, and the job's
// report (the `detect --report` JSON without the command line's header).
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <optional>
#include <string>
#include <vector>

#include "datasets/io/io_error.h"
#include "datasets/io/truth_labels.h"
#include "implicitfit/detect.h"
#include "model/file/model_json.h"
#include "python/arrays.h"
#include "python/bindings.h"
#include "python/input_cloud.h"
#include "python/json_to_python.h"
#include "python/options.h"

namespace implicitfit::python {
namespace {

struct PyDetectedPrimitive {
  std::string name, kind, normal_side;
  py::object model, indices;
  double rms_distance = 0.0;

  std::string Repr() const {
    return "DetectedPrimitive(name='" + name + "', kind='" + kind +
           "', points=" + std::to_string(py::len(indices)) +
           ", rms_distance=" + py::repr(py::float_(rms_distance)).cast<std::string>() + ")";
  }
};

struct PyDetectResult {
  py::list primitives;
  py::object labels, report;

  std::string Repr() const {
    const py::dict r = report.cast<py::dict>();
    std::string text = "DetectResult(primitives=" + std::to_string(py::len(primitives));
    if (r.contains("kinds")) text += ", kinds=" + py::repr(r["kinds"]).cast<std::string>();
    if (r.contains("unassigned"))
      text += ", unassigned=" + py::str(r["unassigned"]).cast<std::string>();
    return text + " of " + std::to_string(py::len(labels)) + " points)";
  }
};

DetectionOptions OptionsFrom(long long seed, std::optional<double> threshold,
                             std::optional<long long> min_points,
                             std::optional<std::vector<std::string>> kinds) {
  DetectionOptions options;
  options.seed = SeedFrom(seed);
  if (threshold) options.threshold = PositiveFrom(*threshold, "threshold");
  if (min_points) {
    if (*min_points < 1 || *min_points > (1LL << 31) - 1)
      throw py::value_error("min_points: must be in [1, 2^31 - 1]");
    options.min_points = static_cast<int>(*min_points);
  }
  if (kinds) {
    if (kinds->empty()) throw py::value_error("kinds: no kind given");
    std::string list;
    for (const std::string& k : *kinds) list += (list.empty() ? "" : ",") + k;
    options.kinds.clear();
    try {
      for (NodeType kind : ParseKindList(list, "kinds"))
        if (std::find(options.kinds.begin(), options.kinds.end(), kind) == options.kinds.end())
          options.kinds.push_back(kind);
    } catch (const InputError& e) {
      throw py::value_error(e.what());
    }
  }
  std::string error;
  if (!options.IsValid(&error)) throw py::value_error(error);
  return options;
}

PyDetectResult Detect(const py::handle& points, const py::handle& normals, long long seed,
                      std::optional<double> threshold, std::optional<long long> min_points,
                      std::optional<std::vector<std::string>> kinds) {
  const DetectionOptions options = OptionsFrom(seed, threshold, min_points, kinds);
  InputCloud in = ReadInputCloud(points, normals, 3);
  CloudDetection detection;
  {
    py::gil_scoped_release release;
    EstimateNormalsIfMissing(&in);
    detection = DetectCloud(std::move(in.cloud), "<array>", in.action, options);
  }
  PyDetectResult out;
  const std::vector<DetectedPrimitive>& found = detection.result.primitives;
  for (size_t k = 0; k < found.size() && k < detection.scene.primitives.size(); ++k) {
    const ScenePrimitive& s = detection.scene.primitives[k];
    PyDetectedPrimitive p;
    p.name = s.name;
    p.kind = NodeTypeName(found[k].kind);
    p.normal_side = s.normal_side;
    p.model = ToPython(ModelToJson(s.model).at("root"));  // as the scene file writes it
    p.indices = ArrayFromIndices(found[k].points);
    p.rms_distance = s.rms_distance;
    out.primitives.append(py::cast(std::move(p)));
  }
  std::vector<int> labels = detection.result.labels;
  labels.resize(detection.cloud.size(), -1);
  out.labels = ArrayFromIndices(labels);
  out.report = ToPython(detection.report);
  return out;
}

}  // namespace

void BindDetect(py::module_& m) {
  py::class_<PyDetectedPrimitive>(m, "DetectedPrimitive",
                                  "One detected primitive: model (the scene file's model node, a "
                                  "dict), kind, indices, rms_distance.")
      .def_readonly("name", &PyDetectedPrimitive::name, "\"p0\", \"p1\", ... as in the scene file")
      .def_readonly("kind", &PyDetectedPrimitive::kind, "plane, sphere, cylinder, cone or torus")
      .def_readonly("model", &PyDetectedPrimitive::model,
                    "The model-file node, e.g. {\"type\": \"sphere\", \"center\": [...], "
                    "\"radius\": r}")
      .def_readonly("indices", &PyDetectedPrimitive::indices,
                    "(K,) int64: the indices of its points, ascending")
      .def_readonly("rms_distance", &PyDetectedPrimitive::rms_distance,
                    "RMS of f over its points")
      .def_readonly("normal_side", &PyDetectedPrimitive::normal_side,
                    "\"outward\", \"inward\" or \"unknown\": the normals against grad f")
      .def("__repr__", &PyDetectedPrimitive::Repr);
  py::class_<PyDetectResult>(m, "DetectResult",
                             "The result of detect(): primitives, labels, report.")
      .def_readonly("primitives", &PyDetectResult::primitives,
                    "The DetectedPrimitive list, largest first")
      .def_readonly("labels", &PyDetectResult::labels,
                    "(N,) int64: each point's index into primitives, -1 when unassigned")
      .def_readonly("report", &PyDetectResult::report,
                    "The job's report (`implicitfit detect --report` without its header)")
      .def("__repr__", &PyDetectResult::Repr);
  m.def("detect", &Detect, py::arg("points"), py::arg("normals") = py::none(), py::kw_only(),
        py::arg("seed") = 1, py::arg("threshold") = py::none(),
        py::arg("min_points") = py::none(), py::arg("kinds") = py::none(),
        "Every primitive of a cloud, as `implicitfit detect CLOUD`: a DetectResult.\n"
        "points, normals: (N, 3) arrays (normals None: estimated and oriented as the command\n"
        "line does for a file without normals). seed: as `--seed` (default 1, the command\n"
        "line's); threshold: the distance band (None: from the data's noise); min_points: the\n"
        "smallest primitive (None: max(10, N / 500)); kinds: e.g. [\"plane\", \"cylinder\"]\n"
        "(None: plane, sphere, cylinder, cone, torus).");
}

}  // namespace implicitfit::python
