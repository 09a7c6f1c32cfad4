// fit CLOUD --model bspline-surface --grid NUxNV [--degree p] --out M.json: a B-spline patch by
// orthogonal distance (fit/splines/bspline_surface_fitter.h); fit CLOUD --model bspline-volume
// --cells n [--degree k] [--convex] --out M.json: a trivariate B-spline implicit
// (fit/splines/bspline_volume_fitter.h), certified convex with --convex. Exit 0 success; 1 the
// fit failed or the certificate failed (no model written); 2 invalid usage or input.
#include <cstdio>
#include <iostream>
#include <nlohmann/json.hpp>

#include "apps/fit/fit_model_kinds.h"
#include "apps/report_header.h"
#include "datasets/io/atomic_file.h"
#include "datasets/io/io_error.h"
#include "datasets/io/model_file.h"
#include "datasets/normals/oriented_cloud.h"
#include "fit/splines/bspline_surface_fitter.h"
#include "fit/splines/bspline_volume_fitter.h"

namespace implicitfit {
namespace {

int Finish(const ModelFitRequest& request, bool success, const std::string& message,
           const Model& model, const nlohmann::json& report) {
  if (!request.report.empty()) WriteReportFile(request.report, report);
  if (!success) {
    std::cerr << "implicitfit fit: " << request.cloud << ": " << request.kind
              << " fit failed: " << message << "\n";
    return 1;
  }
  WriteModelFile(model, request.out);
  return 0;
}

int RunSurfaceFit(const ModelFitRequest& request) {
  if (request.grid.empty()) throw InputError("--model bspline-surface needs --grid NUxNV");
  if (request.convex) throw InputError("--convex applies to bspline-volume and the patch kinds");
  if (request.cells > 0) throw InputError("--cells applies to bspline-volume and patch-mesh");
  SurfaceFitOptions options;
  int counts[2];
  ParseCounts(request.grid, 2, "8x6", counts);
  options.count_u = counts[0];
  options.count_v = counts[1];
  if (request.degree > 0) options.degree = request.degree;
  std::string error;
  if (!options.IsValid(&error)) throw InputError(error);
  std::string normals;
  const PointCloud cloud = ReadOrientedCloud(request.cloud, &normals);
  const SurfaceFitResult r = FitBSplineSurface(cloud.points, cloud.normals, options);
  const nlohmann::json report = {
      {"kind", "bspline-surface"},  {"success", r.success},
      {"message", r.message},       {"points", cloud.size()},
      {"grid", {r.count_u, r.count_v}}, {"degree", r.degree},
      {"rms_distance", r.rms},      {"initial_rms_distance", r.initial_rms},
      {"mean_normal_angle_deg", r.mean_normal_angle_deg},
      {"correction_rounds", r.correction_rounds},
      {"refined", r.refined},       {"refine_iterations", r.refine_iterations},
      {"seconds", r.seconds},       {"normals", normals}};
  const int code = Finish(request, r.success, r.message, r.success ? r.ToModel() : Model(), report);
  if (code == 0)
    std::printf("points %zu  grid %dx%d  degree %d  rms %.6g  (start %.6g)  normal angle %.3g deg  "
                "%.3f s\n",
                cloud.size(), r.count_u, r.count_v, r.degree, r.rms, r.initial_rms,
                r.mean_normal_angle_deg, r.seconds);
  return code;
}

int RunVolumeFit(const ModelFitRequest& request) {
  if (!request.grid.empty()) throw InputError("--grid applies to bspline-surface and partition");
  VolumeFitOptions options;
  if (request.cells > 0) options.cells = request.cells;
  if (request.degree > 0) options.degree = request.degree;
  options.convex = request.convex;
  std::string error;
  if (!options.IsValid(&error)) throw InputError(error);
  std::string normals;
  const PointCloud cloud = ReadOrientedCloud(request.cloud, &normals);
  const VolumeFitResult r = FitBSplineVolume(cloud.points, cloud.normals, options);
  const SplineStructure& s = r.structure;
  nlohmann::json report = {{"kind", "bspline-volume"},
                           {"success", r.success},
                           {"message", r.message},
                           {"points", cloud.size()},
                           {"degree", options.degree},
                           {"cells", {s.cells[0], s.cells[1], s.cells[2]}},
                           {"box", std::vector<double>(s.box, s.box + 6)},
                           {"rms_distance", r.rms},
                           {"initial_rms_distance", r.initial_rms},
                           {"mean_normal_angle_deg", r.mean_normal_angle_deg},
                           {"iterations", r.iterations},
                           {"convex_constraint", options.convex},
                           {"certified_convex", r.certified_convex},
                           {"seconds", r.seconds},
                           {"normals", normals}};
  if (options.convex) {
    report["min_eigenvalue"] = r.certificate.min_eigenvalue;
    report["certified_cells"] = r.certificate.certified_cells;
    report["unconstrained_rms_distance"] = r.unconstrained_rms;
  }
  const int code = Finish(request, r.success, r.message, r.success ? r.ToModel() : Model(), report);
  if (code == 0)
    std::printf("points %zu  cells %dx%dx%d  degree %d  rms %.6g  (start %.6g)  normal angle %.3g "
                "deg  certified convex %s  %.3f s\n",
                cloud.size(), s.cells[0], s.cells[1], s.cells[2], options.degree, r.rms,
                r.initial_rms, r.mean_normal_angle_deg, r.certified_convex ? "yes" : "no",
                r.seconds);
  return code;
}

}  // namespace

bool IsSplineKind(const std::string& kind) {
  return kind == "bspline-surface" || kind == "bspline-volume";
}

int RunSplineFit(const ModelFitRequest& request) {
  if (!request.tetrahedron.empty())
    throw InputError("--tetrahedron applies to quadric-patch and cubic-patch");
  return request.kind == "bspline-surface" ? RunSurfaceFit(request) : RunVolumeFit(request);
}

}  // namespace implicitfit
