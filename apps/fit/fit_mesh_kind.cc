// fit CLOUD --model patch-mesh [--degree k] [--cells n | --cell h] [--continuity 0|1]
//     [--convex] --out MODEL.json [--report R.json]: a Bernstein mesh
// (fit/bernstein/bernstein_mesh_fitter.h). Exit 0 success; 1 the fit failed or (--convex) the
// certificate failed, no model written; 2 invalid usage or input.
#include <cstdio>
#include <iostream>
#include <nlohmann/json.hpp>

#include "apps/fit/fit_model_kinds.h"
#include "apps/report_header.h"
#include "datasets/io/atomic_file.h"
#include "datasets/io/io_error.h"
#include "datasets/io/model_file.h"
#include "datasets/normals/oriented_cloud.h"
#include "fit/bernstein/bernstein_mesh_fitter.h"

namespace implicitfit {

bool IsMeshKind(const std::string& kind) { return kind == "patch-mesh"; }

ModelKindFit FitMeshCloud(const ModelFitRequest& request) {
  MeshFitOptions options;
  options.degree = request.degree > 0 ? request.degree : 3;
  options.cells = request.cells;
  options.cell = request.cell;
  options.continuity = request.continuity;
  options.convex = request.convex;
  if (!request.tetrahedron.empty())
    throw InputError("--tetrahedron applies to quadric-patch and cubic-patch");
  std::string error;
  if (!options.IsValid(&error)) throw InputError(error);
  std::string normals;
  const PointCloud cloud = ReadOrientedCloud(request.cloud, &normals);
  const MeshFitResult r = FitBernsteinMesh(cloud.points, cloud.normals, options);
  const BernsteinGrid& g = r.grid;
  const nlohmann::json report = {{"success", r.success},
                                 {"message", r.message},
                                 {"points", cloud.size()},
                                 {"inliers", cloud.size()},
                                 {"degree", options.degree},
                                 {"continuity", options.continuity},
                                 {"grid",
                                  {{"origin", {g.origin[0], g.origin[1], g.origin[2]}},
                                   {"cell", g.cell},
                                   {"cells", {g.cells[0], g.cells[1], g.cells[2]}}}},
                                 {"patches", r.tetrahedra},
                                 {"rms_distance", r.rms},
                                 {"initial_rms_distance", r.initial_rms},
                                 {"unconstrained_rms_distance", r.unconstrained_rms},
                                 {"mean_normal_angle_deg", r.mean_normal_angle_deg},
                                 {"continuity_defect", r.continuity_defect},
                                 {"convex_constraint", options.convex},
                                 {"certified_tetrahedra", r.certified_tetrahedra},
                                 {"certified_convex", r.certified_convex},
                                 {"min_eigenvalue", r.min_eigenvalue},
                                 {"iterations", r.iterations},
                                 {"kept_initialisation", r.kept_initialisation},
                                 {"box_sign_errors", r.box_sign_errors},
                                 {"seconds", r.seconds},
                                 {"normals", normals}};
  return MakeModelKindFit(r, report, cloud.size());
}

int RunMeshFit(const ModelFitRequest& request) {
  const ModelKindFit fit = FitMeshCloud(request);
  const nlohmann::json& rep = fit.report;
  if (!request.report.empty()) WriteReportFile(request.report, rep);
  if (!fit.success) {
    std::cerr << "implicitfit fit: " << request.cloud << ": patch-mesh fit failed: " << fit.message
              << "\n";
    return 1;
  }
  WriteModelFile(fit.model, request.out);
  const auto& cells = rep["grid"]["cells"];
  std::printf(
      "points %zu  patches %lld (%dx%dx%d cubes, degree %d, C%d)  rms %.6g  normal angle %.3g deg  "
      "continuity defect %.3g  certified convex on the box %s (%lld tetrahedra certified, min "
      "eigenvalue "
      "%.3g)  %.3f s\n",
      fit.points, rep["patches"].get<long long>(), cells[0].get<int>(), cells[1].get<int>(),
      cells[2].get<int>(), rep["degree"].get<int>(), rep["continuity"].get<int>(), fit.rms,
      rep["mean_normal_angle_deg"].get<double>(), rep["continuity_defect"].get<double>(),
      fit.certified_convex ? "yes" : "no", rep["certified_tetrahedra"].get<long long>(),
      rep["min_eigenvalue"].get<double>(), rep["seconds"].get<double>());
  if (request.convex)
    std::printf("unconstrained fit (no convexity constraint): rms %.6g\n",
                rep["unconstrained_rms_distance"].get<double>());
  return 0;
}

}  // namespace implicitfit
