// implicitfit.reconstruct: the verified solid of a cloud, as `implicitfit reconstruct CLOUD` builds
// it without a scene (implicitfit/reconstruct.h: ReconstructCloud — detect, then the solid), on
// NumPy arrays. The GIL is released for the normals and the reconstruction. The result is a
// ReconstructResult: the model file as a dict (None unless the solid verified, or was built and
// keep_unverified is set: then marked unverified, as `reconstruct --keep-unverified` writes it),
// success, verified, and the job's report.
#include <pybind11/pybind11.h>

#include <string>

#include "implicitfit/reconstruct.h"
#include "model/file/model_json.h"
#include "python/arrays.h"
#include "python/bindings.h"
#include "python/input_cloud.h"
#include "python/json_to_python.h"
#include "python/options.h"

namespace implicitfit::python {
namespace {

struct PyReconstructResult {
  py::object model = py::none();
  bool success = false, verified = false;
  std::string expression, message;
  py::object labels, report;

  std::string Repr() const {
    std::string text = "ReconstructResult(success=" + std::string(success ? "True" : "False") +
                       ", verified=" + (verified ? "True" : "False");
    if (!expression.empty())
      text += ", expression=" + py::repr(py::str(expression)).cast<std::string>();
    if (!success) text += ", message=" + py::repr(py::str(message)).cast<std::string>();
    return text + ", model=" + (model.is_none() ? "None" : "{...}") + ")";
  }
};

PyReconstructResult Reconstruct(const py::handle& points, const py::handle& normals,
                                long long seed, bool keep_unverified) {
  ReconstructJobOptions options;
  options.seed = SeedFrom(seed);
  InputCloud in = ReadInputCloud(points, normals, 3);
  CloudReconstruction job;
  {
    py::gil_scoped_release release;
    EstimateNormalsIfMissing(&in);
    job = ReconstructCloud(std::move(in.cloud), "<array>", in.action, options);
  }
  const SolidReconstruction& r = job.result;
  const bool built = r.verification.points > 0;  // a solid was built (verified or not)
  const bool keep = r.success || (keep_unverified && built);
  job.report["model_written"] = keep;  // as `reconstruct` reports it
  PyReconstructResult out;
  out.success = r.success;
  out.verified = r.verification.verified;
  out.expression = r.expression;
  out.message = r.message;
  if (keep) out.model = ToPython(ModelToJson(r.model));
  out.labels = ArrayFromIndices(job.labels);
  out.report = ToPython(job.report);
  return out;
}

}  // namespace

void BindReconstruct(py::module_& m) {
  py::class_<PyReconstructResult>(m, "ReconstructResult",
                                  "The result of reconstruct(): model, success, verified, report.")
      .def_readonly("model", &PyReconstructResult::model,
                    "The model file as a dict (what `reconstruct --out` writes); None when the "
                    "solid did not verify (unless keep_unverified)")
      .def_readonly("success", &PyReconstructResult::success,
                    "The solid was built and verified")
      .def_readonly("verified", &PyReconstructResult::verified,
                    "The verification passed (report[\"verification\"])")
      .def_readonly("expression", &PyReconstructResult::expression,
                    "The CSG expression of the solid, e.g. \"p0 & p1 & !p2\"")
      .def_readonly("message", &PyReconstructResult::message, "Why it failed, or \"verified\"")
      .def_readonly("labels", &PyReconstructResult::labels,
                    "(N,) int64: detect's primitive of each point, -1 when unassigned")
      .def_readonly("report", &PyReconstructResult::report,
                    "The job's report (`implicitfit reconstruct --report` without its header)")
      .def("__repr__", &PyReconstructResult::Repr);
  m.def("reconstruct", &Reconstruct, py::arg("points"), py::arg("normals") = py::none(),
        py::kw_only(), py::arg("seed") = 1, py::arg("keep_unverified") = false,
        "The solid of a cloud, as `implicitfit reconstruct CLOUD` without a scene (detect, then\n"
        "the solid): a ReconstructResult. normals None: estimated and oriented as the command\n"
        "line does. seed: as `--seed` (default 1, the command line's). keep_unverified: return\n"
        "the model of a solid that was built but failed verification (marked unverified).");
}

}  // namespace implicitfit::python
