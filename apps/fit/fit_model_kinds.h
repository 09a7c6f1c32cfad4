// The fits of `implicitfit fit` beyond single primitives:
//   --init MODEL.json      every free parameter of a model tree (fit/tree/tree_fitter.h)
//   --model quadric-patch | cubic-patch [--degree k] [--convex] [--tetrahedron 12 numbers]
//                          a Bernstein patch (fit/bernstein/patch_fitter.h)
//   --model box | paraboloid | capsule
//                          a robust start (fit/tree/shape_starts.h), then the tree fitter
//   --model partition --grid AxBxC [--child plane|quadric]
//                          the sparse linear start (fit/tree/partition_start.h), then the tree fitter
//   --model bspline-surface --grid NUxNV [--degree p] | bspline-volume --cells n [--convex]
//                          the spline fits of fit/splines/
// Each reads the cloud, fits, writes the report (when asked) and, on success, the model file;
// returns the exit code (0 success, 1 the fit failed or the constraint cannot be met).
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "fit/common/progress.h"
#include "fit/tree/tree_fitter.h"
#include "model/model.h"

namespace implicitfit {

struct ModelFitRequest {
  std::string cloud, out, report;
  std::string init;  // --init
  std::string kind;  // quadric-patch / cubic-patch
  int degree = 0;    // 0: from the kind
  bool convex = false;
  std::vector<double> tetrahedron;  // empty or 12 numbers
  // Guo §3 shape control (patch kinds): vertices 1..4; "I=nx,ny,nz"; "I,J".
  std::vector<int> through_vertices;
  std::vector<std::string> vertex_normals, through_edges;
  bool HasShapeConstraints() const {
    return !through_vertices.empty() || !vertex_normals.empty() || !through_edges.empty();
  }
  int cells = 0;                // patch-mesh: --cells (0: default)
  double cell = 0.0;            // patch-mesh: --cell (0: from cells)
  int continuity = 1;           // patch-mesh: --continuity
  int levels = 0;               // patch-mesh: --levels (> 0: adaptive refinement)
  bool quiet = false;           // patch-mesh: --quiet (no progress on stderr)
  std::string grid;             // partition: --grid AxBxC
  std::string child = "plane";  // partition: --child plane|quadric
};

// The fit of one cloud for the Bernstein kinds, shared by `fit` and `batch`: the report that
// `fit --report` writes and, on success, the model. Throws InputError for bad input.
struct ModelKindFit {
  bool success = false;
  std::string message;
  size_t points = 0;
  double rms = 0.0;
  bool certified_convex = false;
  nlohmann::json report;
  std::string brief;  // the result's BriefReport() (patch kinds)
  Model model;
};
// The common fields of a patch or patch-mesh fit result (success, message, rms,
// certified_convex, ToModel()) with its report.
template <typename Result>
ModelKindFit MakeModelKindFit(const Result& r, nlohmann::json report, size_t points) {
  ModelKindFit out;
  out.report = std::move(report);
  out.success = r.success;
  out.message = r.message;
  out.points = points;
  out.rms = r.rms;
  out.certified_convex = r.certified_convex;
  if (r.success) out.model = r.ToModel();
  return out;
}
ModelKindFit FitPatchCloud(const ModelFitRequest& request);
ModelKindFit FitMeshCloud(const ModelFitRequest& request, ProgressCallback progress = {});

bool IsPatchKind(const std::string& kind);

// Every kind `fit --model` takes, in the order its help lists them: the primitives of the
// robust fitter, the Bernstein patches, the shapes, the patch mesh, the soft partition and the
// splines. The help text and the "unknown kind" error are built from this one list.
const std::vector<std::string>& FitCommandKinds();
// FitCommandKinds() joined with ", ".
std::string FitCommandKindList();
// The tree fitter's options of the command line: the defaults, with the work limit
// (fit/tree/tree_fitter.h: kMaxTreeFitWork).
inline TreeFitOptions CommandLineTreeFitOptions() {
  TreeFitOptions options;
  options.max_work = kMaxTreeFitWork;
  return options;
}
// box, paraboloid, capsule: a robust start (fit/tree/shape_starts.h), then the tree fitter; the
// report is the --init one plus "kind" and the start's parameters ("start").
bool IsShapeKind(const std::string& kind);
// The report fields of a tree fit started from `start`: the result's ToJson (success, message,
// points, inliers, rms_distance, sigma, mean_normal_angle_deg, iterations, seconds, normals,
// termination, "parameters"), and per parameter name its standard deviation at the optimum from the inliers
// ("standard_deviations", fit/tree/tree_covariance.h) and start value ("start").
void AddTreeFitFigures(const TreeFitResult& r, const Model& start,
                       const std::vector<Eigen::Vector3d>& points, const std::string& normals,
                       nlohmann::json* report);
// "AxBxC" (n counts >= 1 of at most 4 digits joined by x) into counts; InputError naming --grid
// and `example` otherwise.
void ParseCounts(const std::string& text, int n, const std::string& example, int* counts);
// --model bspline-surface --grid NUxNV [--degree p] and --model bspline-volume --cells n
// [--degree k] [--convex] (apps/fit/fit_spline_kinds.cc, fit/splines/).
bool IsSplineKind(const std::string& kind);
int RunSplineFit(const ModelFitRequest& request);
// --model partition --grid AxBxC [--child plane|quadric]: the linear start of
// fit/tree/partition_start.h, then the tree fitter (apps/fit/fit_partition_kind.cc).
int RunPartitionFit(const ModelFitRequest& request);
int RunShapeFit(const ModelFitRequest& request, unsigned seed);
int RunTreeFit(const ModelFitRequest& request);
int RunPatchFit(const ModelFitRequest& request);
// --model patch-mesh [--degree k] [--cells n | --cell h] [--continuity 0|1] [--convex]: a
// Bernstein mesh (fit/bernstein/bernstein_mesh_fitter.h), apps/fit/fit_mesh_kind.cc.
bool IsMeshKind(const std::string& kind);
int RunMeshFit(const ModelFitRequest& request);

}  // namespace implicitfit
