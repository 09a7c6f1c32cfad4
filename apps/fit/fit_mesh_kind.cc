// fit CLOUD --model patch-mesh [--degree k] [--cells n | --cell h] [--continuity 0|1]
//     [--levels L] [--convex] --out MODEL.json [--report R.json] [--quiet]: a Bernstein mesh
//     (implicitfit/patch_mesh.h); progress on stderr (each fit's size and RMS, each refined
//     try's fate) unless --quiet.
// Exit 0 success; 1 the fit failed or (--convex) the certificate failed, no model written; 2
// invalid usage or input.
#include <cstdio>
#include <iostream>

#include "apps/fit/fit_model_kinds.h"
#include "apps/progress_printer.h"
#include "apps/report_header.h"
#include "datasets/io/io_error.h"
#include "datasets/io/model_file.h"
#include "datasets/normals/oriented_cloud.h"
#include "implicitfit/patch_mesh.h"

namespace implicitfit {

bool IsMeshKind(const std::string& kind) { return kind == "patch-mesh"; }

ModelKindFit FitMeshCloud(const ModelFitRequest& request, ProgressCallback progress) {
  PatchMeshJobOptions options = PatchMeshJobOptions::FromCommandLine(
      request.degree > 0 ? request.degree : 3, request.cells, request.cell, request.continuity,
      request.levels, request.convex);
  if (!request.tetrahedron.empty())
    throw InputError("--tetrahedron applies to quadric-patch and cubic-patch");
  std::string error;
  if (!options.IsValid(&error)) throw InputError(error);
  options.fit.progress = std::move(progress);
  std::string normals;
  const PointCloud cloud = ReadOrientedCloud(request.cloud, &normals);
  const PatchMeshJobResult job = FitPatchMeshJob(cloud.points, cloud.normals, options, normals);
  ModelKindFit fit =
      MakeModelKindFit(job.result, job.ToJson(CommandReportHeader(request.cloud)), job.points);
  fit.brief = job.BriefReport();
  return fit;
}

int RunMeshFit(const ModelFitRequest& request) {
  const ModelKindFit fit = FitMeshCloud(request, StderrProgress("fit", request.quiet));
  if (!request.report.empty()) WriteReportFile(request.report, fit.report);
  if (!fit.success) {
    std::cerr << "implicitfit fit: " << request.cloud << ": patch-mesh fit failed: " << fit.message
              << "\n";
    return 1;
  }
  WriteModelFile(fit.model, request.out);
  std::printf("%s\n", fit.brief.c_str());
  return 0;
}

}  // namespace implicitfit
