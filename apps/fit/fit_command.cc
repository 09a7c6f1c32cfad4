// implicitfit fit CLOUD --model KIND --out MODEL.json [--report R.json] [--seed s]
//                 [--fix FIELD=V[,V,V] ...] [--threshold t | --band b]
// Fits one primitive (fit/primitive/primitive_fitter.h) that must be real (fit/detect/
// checked_fit.h: the detector's candidate checks); prints the model and its residual figures.
// --threshold: a fixed inlier distance; --band: the adaptive band's start (default: from the
// cloud's noise and spacing). Exit 0 on success; 1 when the fit fails (too few inliers, no
// convergence, no real primitive of the kind) with the reason, and no model file; 2 for
// invalid usage or input.
#include <algorithm>
#include <cstdio>
#include <iostream>
#include <optional>
#include <nlohmann/json.hpp>

#include "apps/command.h"
#include "apps/report_header.h"
#include "apps/fit/fit_job.h"
#include "apps/fit/fit_model_kinds.h"
#include "apps/view_outputs.h"
#include "datasets/io/atomic_file.h"
#include "datasets/io/io_error.h"
#include "datasets/io/model_file.h"
#include "fit/primitive/primitive_fitter.h"
#include "model/file/model_json.h"

namespace implicitfit {
namespace {

struct FitArgs {
  std::string cloud, kind, out, report, init;
  unsigned seed = 1;
  double threshold = 0.0, band = 0.0;
  std::vector<std::string> fixes;
  bool convex = false;
  int degree = 0;
  std::vector<double> tetrahedron;
  std::vector<int> through_vertices;
  std::vector<std::string> vertex_normals, through_edges;
  std::string estimator = "robust";
  int cells = 0;
  double cell = 0.0;
  int continuity = 1;
  int levels = 0;
  bool quiet = false;
  std::string grid, child = "plane";
  std::string view, ply;                 // --view PAGE.html, --ply RESIDUALS.ply
  std::optional<std::vector<int>> inliers;  // of a primitive fit, for the view and the PLY
  std::optional<Model> model;  // the primitive fit's model, for the view and the PLY
};

}  // namespace

CommandAction AddFitCommand(CLI::App& app) {
  auto* cmd = app.add_subcommand("fit", "Fit a model to an oriented point cloud");
  auto a = std::make_shared<FitArgs>();
  cmd->add_option("CLOUD", a->cloud,
                  "Point cloud (.xyz/.pwn/.txt/.xyzl/.ply/.pcd; normals estimated when absent)")
      ->required();
  auto* model_opt =
      cmd->add_option("--model", a->kind, "Kind to fit: " + FitCommandKindList());
  auto* init_opt = cmd->add_option("--init", a->init,
                                   "Fit every free parameter of this model tree (primitive "
                                   "parameters, delta and epsilon, control points)");
  model_opt->excludes(init_opt);
  cmd->add_option("--out", a->out, "Output model file (JSON)")->required();
  cmd->add_option("--report", a->report, "Write a JSON report of the fit");
  cmd->add_flag("--quiet", a->quiet, "patch-mesh: no progress on stderr");
  cmd->add_option("--seed", a->seed, "Random seed (the fit is deterministic for a seed)");
  auto* threshold_opt =
      cmd->add_option("--threshold", a->threshold,
                      "Fixed inlier distance: |f| < t in every round (as Open3D's and PCL's "
                      "distance threshold)")
          ->check(CLI::PositiveNumber);
  cmd->add_option("--band", a->band,
                  "Adaptive inlier band: start at b, then 3 x the estimated noise (default "
                  "start: 3 x the cloud's noise, at least 0.1 x its spacing)")
      ->check(CLI::PositiveNumber)
      ->excludes(threshold_opt);
  cmd->add_option("--fix", a->fixes,
                  "Keep a parameter constant, e.g. --fix radius=2 --fix axis=0,0,1");
  cmd->add_option("--estimator", a->estimator,
                  "robust (default: trimmed maximum likelihood), least-squares (orthogonal "
                  "distances of every point, "
                  "ISO 10360-6) or minimum-zone (smallest max |distance|, ISO 1101)");
  cmd->add_flag("--convex", a->convex,
                "Constrain the Bernstein patch or the bspline-volume to be convex (certified)")
      ->group("Bernstein patches");
  cmd->add_option("--degree", a->degree,
                  "Patch degree (2..4; default 2 for quadric-patch, 3 for cubic-patch; patch-mesh "
                  "2..5, default 3; bspline-surface 1..7, bspline-volume 1..5, default 3)")
      ->check(CLI::Range(1, 7))
      ->group("Bernstein patches");
  cmd->add_option("--tetrahedron", a->tetrahedron,
                  "Patch tetrahedron x1,y1,z1,...,x4,y4,z4 (default: encloses the cloud)")
      ->delimiter(',')
      ->expected(12)
      ->group("Bernstein patches");
  auto* cells_opt = cmd->add_option("--cells", a->cells,
                                    "patch-mesh, bspline-volume: cubes along the longest edge of "
                                    "the cloud's box (default 8; patch-mesh 4 with --convex)")
                        ->check(CLI::Range(1, 200))
                        ->group("Bernstein patches");
  cmd->add_option("--cell", a->cell, "patch-mesh: cube edge length (instead of --cells)")
      ->check(CLI::PositiveNumber)
      ->excludes(cells_opt)
      ->group("Bernstein patches");
  cmd->add_option("--continuity", a->continuity,
                  "patch-mesh: 0 (C0, with C1 as a penalty off the creases) or 1 (C1, default)")
      ->check(CLI::Range(0, 1))
      ->group("Bernstein patches");
  cmd->add_option("--levels", a->levels,
                  "patch-mesh: refine the cubes whose points' residuals exceed the noise, up to "
                  "L levels below the base grid (octree; crease leaves C0; default 0: uniform)")
      ->check(CLI::Range(0, 6))
      ->group("Bernstein patches");
  cmd->add_option("--grid", a->grid,
                  "partition: A x B x C cells at equal spacing over the cloud's box + 5%, e.g. "
                  "3x3x2; bspline-surface: NU x NV control points, e.g. 8x6")
      ->group("Soft partitions");
  cmd->add_option("--child", a->child,
                  "partition: the child of every cell, plane (default), quadric or quadric-patch")
      ->group("Soft partitions");
  cmd->add_option("--through-vertex", a->through_vertices,
                  "Patch passes exactly through tetrahedron vertex I (1..4): b_{k e_I} = 0")
      ->check(CLI::Range(1, 4))
      ->group("Bernstein patches");
  cmd->add_option("--vertex-normal", a->vertex_normals,
                  "I=nx,ny,nz: through vertex I with grad f parallel to n (outward)")
      ->group("Bernstein patches");
  cmd->add_option("--through-edge", a->through_edges,
                  "I,J: the edge between vertices I and J lies on the patch")
      ->group("Bernstein patches");
  cmd->add_option("--view", a->view, "Also write a page of the result (docs/view.md)");
  cmd->add_option("--ply", a->ply, "Also write the cloud with each point's residual (PLY)");
  const auto run = [a]() {
    ModelFitRequest request;
    request.cloud = a->cloud;
    request.out = a->out;
    request.report = a->report;
    request.init = a->init;
    request.kind = a->kind;
    request.degree = a->degree;
    request.convex = a->convex;
    request.tetrahedron = a->tetrahedron;
    request.through_vertices = a->through_vertices;
    request.vertex_normals = a->vertex_normals;
    request.through_edges = a->through_edges;
    request.cells = a->cells;
    request.cell = a->cell;
    request.continuity = a->continuity;
    request.levels = a->levels;
    request.quiet = a->quiet;
    request.grid = a->grid;
    request.child = a->child;
    if (a->kind != "partition" && a->kind != "bspline-surface" && !a->grid.empty())
      throw InputError("--grid applies to --model partition and bspline-surface");
    if (request.HasShapeConstraints() && !IsPatchKind(a->kind))
      throw InputError(
          "--through-vertex, --vertex-normal and --through-edge apply to quadric-patch "
          "and cubic-patch");
    const std::vector<std::string>& kinds = FitCommandKinds();
    if (!a->kind.empty() && std::find(kinds.begin(), kinds.end(), a->kind) == kinds.end())
      throw InputError("--model " + a->kind + ": unknown kind (" + FitCommandKindList() + ")");
    if (a->kind == "partition") return RunPartitionFit(request);
    if (IsSplineKind(a->kind)) return RunSplineFit(request);
    if (IsMeshKind(a->kind)) return RunMeshFit(request);
    if (!a->init.empty()) return RunTreeFit(request);
    if (IsPatchKind(a->kind)) return RunPatchFit(request);
    if (IsShapeKind(a->kind)) return RunShapeFit(request, a->seed);
    if (a->convex) throw InputError("--convex applies to quadric-patch and cubic-patch");
    if (a->kind.empty()) throw InputError("--model KIND or --init MODEL.json is required");
    PrimitiveFitOptions options =
        FitOptionsFromArguments(a->kind, a->seed, a->threshold, a->fixes, a->band);
    SetEstimatorFromArgument(a->estimator, &options);
    const CloudFit fit = FitCloudFile(a->cloud, options);
    const PrimitiveFitResult& result = fit.result;
    if (!a->report.empty()) WriteReportFile(a->report, fit.report);
    if (!result.success) {
      std::cerr << "implicitfit fit: " << a->cloud << ": " << NodeTypeName(options.kind)
                << " fit failed: " << result.message << "\n";
      return 1;
    }
    const Model model = result.ToModel(options.kind);
    WriteModelFile(model, a->out);
    std::printf("%s\n", ModelToJson(model)["root"].dump().c_str());
    std::printf("%s\n", result.BriefReport().c_str());
    a->inliers = result.inliers;
    a->model = model;
    return 0;
  };
  return [a, run]() {
    const int code = run();
    if (code == 0 && (!a->view.empty() || !a->ply.empty()))
      // The model as written: --out is renamed into place only when the command returns.
      WriteFitOutputs(a->cloud, a->model ? *a->model : ReadModelFile(CurrentFileLocation(a->out)),
                      a->inliers ? &*a->inliers : nullptr,
                      a->view, a->ply);
    return code;
  };
}

}  // namespace implicitfit
