// implicitfit.fit, fit_tree, fit_patch, fit_patch_mesh: the library's fitters (fit/*.h) on NumPy arrays, with
// the same reports as `implicitfit fit --report` (fit/common/fit_report.h). The arrays are copied
// once into the library's vectors, then the GIL is released for the whole fit (normal estimation
// included), so Python threads can run fits in parallel.
// Normals: given ones are used as they are (scaled to unit length if needed); None estimates and
// orients them as the command line does for a file without normals
// (datasets/normals/normal_estimation.h), so fit(*read_cloud(path)) fits exactly what
// `implicitfit fit path` fits; for `fit`, estimated normals the neighbourhood fits do not trust
// (datasets/normals/normal_trust.h: a few probed points) are dropped and the fit hypothesises
// from points alone, as on the command line.
// estimator= (fit/primitive/estimator.h) as `fit --estimator`.
// fit, fit_tree and fit_patch return a FitResult (model, success, inliers, report) that also
// unpacks as the former (model, report) tuple.
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cmath>
#include <numeric>
#include <optional>
#include <string>

#include "datasets/normals/neighbourhoods.h"
#include "datasets/normals/normal_estimation.h"
#include "datasets/normals/normal_trust.h"
#include "fit/bernstein/patch_fitter.h"
#include "fit/common/fit_report.h"
#include "fit/detect/checked_fit.h"
#include "fit/metrology/primitive_tangent.h"
#include "fit/primitive/primitive_fitter.h"
#include "fit/tree/tree_fitter.h"
#include "implicitfit/patch_mesh.h"
#include "python/arrays.h"
#include "python/bindings.h"
#include "python/input_cloud.h"
#include "python/json_to_python.h"
#include "python/options.h"
#include "python/pair_result.h"

namespace implicitfit::python {
namespace {

// What the fits return: the model (None when the fit failed), its inliers (indices into the
// points, ascending) and the report. Iterating gives (model, report), so `model, report =
// fit(...)` and `fit(...)[0]` work as when `fit` returned that tuple.
struct FitResult {
  py::object model = py::none();
  bool success = false;
  py::object inliers;
  py::object report;

  py::tuple AsTuple() const { return py::make_tuple(model, report); }
  std::string Repr() const {
    const py::dict r = report.cast<py::dict>();
    std::string text = "FitResult(success=" + std::string(success ? "True" : "False");
    if (!model.is_none()) text += ", kind=" + py::repr(model.attr("kind")).cast<std::string>();
    text += ", inliers=" + std::to_string(py::len(inliers)) + " of " +
            (r.contains("points") ? py::str(r["points"]).cast<std::string>() : "?");
    if (r.contains("rms_distance") && success)
      text += ", rms_distance=" + py::repr(r["rms_distance"]).cast<std::string>();
    if (!success && r.contains("message"))
      text += ", message=" + py::repr(r["message"]).cast<std::string>();
    return text + ")";
  }
};

struct PatchFitOutput {
  PatchFitResult result;
  size_t points = 0;
  py::object model, report;
};

PatchFitOutput RunPatchFit(const py::handle& points, const py::handle& normals, int degree,
                           bool convex, const py::handle& tetrahedron) {
  PatchFitOptions options;
  options.degree = degree;
  options.convex = convex;
  if (!tetrahedron.is_none()) {
    const Points v = PointsFromArray(tetrahedron, "tetrahedron");
    if (v.size() != 4) throw py::value_error("tetrahedron: expected a (4, 3) array of vertices");
    double flat[12];
    for (int i = 0; i < 4; ++i)
      for (int c = 0; c < 3; ++c) flat[3 * i + c] = v[i][c];
    try {
      options.tetrahedron = Tetrahedron::FromArray(flat);
    } catch (const std::invalid_argument& e) {
      throw py::value_error(std::string("tetrahedron: ") + e.what());
    }
    options.has_tetrahedron = true;
  }
  std::string error;
  if (!options.IsValid(&error)) throw py::value_error(error);
  InputCloud in = ReadInputCloud(points, normals,
                                 static_cast<size_t>(NumBernsteinControlPoints(options.degree)));
  PatchFitResult result;
  {
    py::gil_scoped_release release;
    EstimateNormalsIfMissing(&in);
    result = FitBernsteinPatch(in.cloud.points, in.cloud.normals, options);
  }
  PatchFitOutput out;
  out.points = in.cloud.size();
  out.model = result.success ? py::cast(result.ToModel()) : py::none();
  out.report = ToPython(PatchFitReport(result, options, in.cloud.size(), in.action));
  out.result = std::move(result);
  return out;
}

// A patch is a least-squares fit of every point: all of them are its inliers.
FitResult PatchFitResultOf(const PatchFitOutput& out) {
  FitResult fit;
  fit.model = out.model;
  fit.success = out.result.success;
  std::vector<int> all(out.result.success ? out.points : 0);
  std::iota(all.begin(), all.end(), 0);
  fit.inliers = ArrayFromIndices(all);
  fit.report = out.report;
  return fit;
}

FitResult PatchFit(const py::handle& points, const py::handle& normals, int degree, bool convex,
                   const py::handle& tetrahedron) {
  return PatchFitResultOf(RunPatchFit(points, normals, degree, convex, tetrahedron));
}

// As `implicitfit fit CLOUD --model patch-mesh` (apps/fit/fit_mesh_kind.cc): the same options,
// the same job (implicitfit/patch_mesh.h), so the same model and report.
FitResult PatchMeshFit(const py::handle& points, const py::handle& normals, int degree,
                       int cells, double cell, int continuity, int levels, bool convex) {
  if (levels < 0) throw py::value_error("levels: must be >= 0, got " + std::to_string(levels));
  const PatchMeshJobOptions options =
      PatchMeshJobOptions::FromCommandLine(degree, cells, cell, continuity, levels, convex);
  std::string error;
  if (!options.IsValid(&error)) throw py::value_error(error);
  InputCloud in = ReadInputCloud(points, normals, 1);
  PatchMeshJobResult job;
  {
    py::gil_scoped_release release;
    EstimateNormalsIfMissing(&in);
    job = FitPatchMeshJob(in.cloud.points, in.cloud.normals, options, in.action);
  }
  FitResult fit;
  fit.success = job.success;
  if (job.success) fit.model = py::cast(job.ToModel());
  std::vector<int> all(job.success ? in.cloud.size() : 0);
  std::iota(all.begin(), all.end(), 0);
  fit.inliers = ArrayFromIndices(all);
  fit.report = ToPython(job.ToJson());
  return fit;
}

// As EstimateNormalsIfMissing, then the command line's trust rule for primitive fits
// (datasets/normals/normal_trust.h: ReadCloudForPrimitiveFit).
// untrusted: the estimated normals it dropped (for the volume check, as the command line's).
void EstimateTrustedNormalsIfMissing(InputCloud* in, std::vector<Eigen::Vector3d>* untrusted) {
  untrusted->clear();
  if (!in->estimate) return;
  EstimateNormalsIfMissing(in);
  const NormalTrust trust = AssessEstimatedNormals(in->cloud.points);
  if (!trust.trusted) {
    untrusted->swap(in->cloud.normals);
    in->cloud.normals.clear();
    in->action = "estimated, not trusted (" + trust.reason + "): fit from points only";
  }
}

FitResult Fit(const py::handle& points, const py::handle& normals, const std::string& kind,
              long long seed, std::optional<double> threshold, std::optional<py::dict> fix,
              const std::string& estimator, std::optional<double> band) {
  if ((kind == "quadric-patch" || kind == "cubic-patch") && estimator != "robust")
    throw py::value_error("estimator " + estimator +
                          ": applies to plane, sphere, cylinder, cone and torus fits");
  if (kind == "quadric-patch" || kind == "cubic-patch")
    return PatchFitResultOf(
        RunPatchFit(points, normals, kind == "quadric-patch" ? 2 : 3, false, py::none()));
  PrimitiveFitOptions options;
  if (!FittableKindFromName(kind, &options.kind))
    throw py::value_error("kind " + kind + ": unknown (" + FittableKindNames() +
                          ", quadric-patch, cubic-patch)");
  options.seed = SeedFrom(seed);
  if (threshold) options.threshold = PositiveFrom(*threshold, "threshold");
  if (band) {
    options.start_band = PositiveFrom(*band, "band");
    if (threshold) throw py::value_error("threshold and band exclude each other");
  }
  if (fix) {
    for (const auto& [field, value] : *fix) {
      const std::string name = py::str(field);
      std::vector<double> values;
      try {
        if (py::isinstance<py::str>(value)) throw py::cast_error();
        if (PySequence_Check(value.ptr()))
          values = value.cast<std::vector<double>>();
        else
          values.push_back(value.cast<double>());  // float, int, NumPy scalars
      } catch (const py::cast_error&) {
        throw py::value_error("fix[" + name + "]: expected a number or a sequence of numbers");
      }
      options.fixed[name] = values;
    }
  }
  if (!EstimatorFromName(estimator, &options.estimator))
    throw py::value_error("estimator " + estimator +
                          ": unknown (robust, least-squares, minimum-zone)");
  std::string error;
  if (!options.IsValid(&error)) throw py::value_error(error);
  // Without normals a fit needs the free parameter count plus one points (fit/metrology/point_hypotheses.h).
  InputCloud in =
      ReadInputCloud(points, normals,
                   normals.is_none() ? static_cast<size_t>(FreeParameterCount(options.kind)) + 1
                                     : static_cast<size_t>(options.min_inliers));
  CheckedFit checked;
  {
    py::gil_scoped_release release;
    std::vector<Eigen::Vector3d> untrusted;
    EstimateTrustedNormalsIfMissing(&in, &untrusted);
    // The command line's checks (fit/detect/checked_fit.h): a real primitive or a failure.
    Neighbourhoods nb;
    if ((in.cloud.has_normals() || !untrusted.empty()) && in.cloud.size() >= kMinCheckedPoints)
      nb = FindNeighbourhoods(in.cloud.points);
    std::string volume;
    if (!untrusted.empty() && !threshold &&
        FillsAVolume(in.cloud.points, untrusted, nb.indices, nb.spacing, &volume)) {
      checked.result.success = false;
      checked.result.termination = FitTermination::kFailure;
      checked.result.message = std::string("no ") + NodeTypeName(options.kind) +
                               " explains the cloud: " + volume + " (threshold fits anyway)";
    } else {
      checked = FitCheckedPrimitive(in.cloud.points, in.cloud.normals, nb.indices, nb.spacing,
                                    options);
    }
  }
  const PrimitiveFitResult& result = checked.result;
  nlohmann::json report = PrimitiveFitReport(result, options.kind, in.cloud.size(), in.action);
  report["check"] = checked.ToJson();
  FitResult fit;
  fit.success = result.success;
  if (result.success) fit.model = py::cast(result.ToModel(options.kind));
  fit.inliers = ArrayFromIndices(result.success ? result.inliers : std::vector<int>());
  fit.report = ToPython(report);
  return fit;
}

FitResult TreeFit(const py::handle& points, const py::handle& normals, const Model& init) {
  InputCloud in = ReadInputCloud(points, normals, init.parameters().size());
  TreeFitResult result;
  {
    py::gil_scoped_release release;
    EstimateNormalsIfMissing(&in);
    result = FitModelTree(init, in.cloud.points, in.cloud.normals, TreeFitOptions{});
  }
  FitResult fit;
  fit.success = result.success;
  if (result.success) fit.model = py::cast(result.model);
  fit.inliers = ArrayFromIndices(result.success ? result.inlier_points : std::vector<int>());
  fit.report = ToPython(TreeFitReport(result, in.cloud.size(), in.action));
  return fit;
}

}  // namespace

void BindFits(py::module_& m) {
  py::class_<FitResult> fit_result(
      m, "FitResult",
      "The result of fit(), fit_tree(), fit_patch() and fit_patch_mesh(): model (Model or None), success, inliers\n"
      "(int64 indices of the points the final fit used, ascending), report (dict). Unpacks as\n"
      "(model, report): `model, report = fit(...)`.");
  fit_result.def_readonly("model", &FitResult::model, "The fitted Model, None when the fit failed")
      .def_readonly("success", &FitResult::success)
      .def_readonly("inliers", &FitResult::inliers,
                    "(K,) int64: the points within the final inlier band (a primitive: |f| and\n"
                    "normals; a tree: |f / |grad f|| < 3 sigma; a patch: every point)")
      .def_readonly("report", &FitResult::report, "The `implicitfit fit --report` JSON as a dict")
      .def("__repr__", &FitResult::Repr);
  UnpacksAsPair(fit_result, "FitResult unpacks as (model, report)");
  m.def(
      "fit", &Fit, py::arg("points"), py::arg("normals") = py::none(), py::arg("kind") = "sphere",
      py::arg("seed") = 0, py::arg("threshold") = py::none(), py::arg("fix") = py::none(),
      py::arg("estimator") = "robust", py::arg("band") = py::none(),
      "Fit of one primitive (plane, sphere, cylinder, cone, torus; quadric-patch and\n"
      "cubic-patch go to fit_patch), as `implicitfit fit CLOUD --model KIND`.\n"
      "points, normals: (N, 3) arrays (normals None: estimated and oriented as the command\n"
      "line does). threshold: a fixed inlier distance |f| < threshold (as Open3D's\n"
      "segment_plane distance_threshold); band: instead, the start of the adaptive band, then 3\n"
      "sigma (None: from the cloud's noise). On a cloud of many surfaces the result is a real\n"
      "primitive of the kind or a failure (report[\"check\"], as the command line).\n"
      "fix: {field: value}, e.g. {\"radius\": 2, \"axis\": [0, 0, 1]}.\n"
      "estimator: \"robust\" (default), \"least-squares\" (every point, ISO 10360-6) or\n"
      "\"minimum-zone\" (Chebyshev, ISO 1101), as `implicitfit fit --estimator`.\n"
      "Returns a FitResult (model, success, inliers, report; unpacks as (model, report)); model\n"
      "is None when the fit fails (report[\"message\"] says why).");
  m.def("fit_tree", &TreeFit, py::arg("points"), py::arg("normals"), py::arg("init"),
        "Fits every free parameter of a model tree (primitive parameters, delta and epsilon of\n"
        "blends, control points), as `implicitfit fit CLOUD --init MODEL.json`. Returns a\n"
        "FitResult (model, success, inliers: within 3 sigma, report; unpacks as (model, report)).");
  m.def("fit_patch", &PatchFit, py::arg("points"), py::arg("normals"), py::arg("degree") = 2,
        py::arg("convex") = false, py::arg("tetrahedron") = py::none(),
        "Fits a Bernstein patch of degree 2..4 (convex=True: enforced and certified convex), as\n"
        "`implicitfit fit CLOUD --model quadric-patch`. tetrahedron: (4, 3) vertices (None: one\n"
        "enclosing the cloud). Returns a FitResult (model, success, inliers: every point,\n"
        "report; unpacks as (model, report)).");
  m.def("fit_patch_mesh", &PatchMeshFit, py::arg("points"), py::arg("normals") = py::none(),
        py::arg("degree") = 3, py::arg("cells") = 0, py::arg("cell") = 0.0,
        py::arg("continuity") = 1, py::arg("levels") = 0, py::arg("convex") = false,
        "Fits a mesh of Bernstein patches on a Kuhn grid over the cloud's box, as `implicitfit\n"
        "fit CLOUD --model patch-mesh`: degree 2..5, cells (cubes on the longest side; 0: from\n"
        "the cloud) or cell (the cube edge), continuity 0 (C0 with soft C1, for CAD parts) or 1,\n"
        "levels: refine L times where the residuals exceed the noise (report[\"refinement\"]),\n"
        "convex: C1, constrained and certified convex on the whole box (not with levels).\n"
        "Returns a FitResult (model, success, inliers: every point, report; unpacks as (model,\n"
        "report)); model is None when the fit fails (report[\"message\"] says why).");
}

}  // namespace implicitfit::python
