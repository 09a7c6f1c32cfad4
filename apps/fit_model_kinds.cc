#include "apps/fit_model_kinds.h"

#include <cstdio>
#include <iostream>
#include <nlohmann/json.hpp>

#include "datasets/atomic_file.h"
#include "datasets/io_error.h"
#include "datasets/model_file.h"
#include "datasets/oriented_cloud.h"
#include "fit/fit_report.h"
#include "fit/patch_fitter.h"
#include "fit/tree_fitter.h"
#include "model/model_json.h"

namespace implicitfit {
namespace {

void Finish(const ModelFitRequest& request, const Model& model, const nlohmann::json& report) {
  if (!request.report.empty()) WriteFileAtomically(request.report, report.dump(2) + "\n");
  WriteModelFile(model, request.out);
  std::printf("%s\n", ModelToJson(model)["root"].dump().c_str());
}

}  // namespace

bool IsPatchKind(const std::string& kind) { return kind == "quadric-patch" || kind == "cubic-patch"; }

int RunTreeFit(const ModelFitRequest& request) {
  const Model init = ReadModelFile(request.init);
  std::string normals;
  const PointCloud cloud = ReadOrientedCloud(request.cloud, &normals);
  const TreeFitResult r = FitModelTree(init, cloud.points, cloud.normals, TreeFitOptions{});
  const nlohmann::json report = TreeFitReport(r, cloud.size(), normals);
  if (!r.success) {
    if (!request.report.empty()) WriteFileAtomically(request.report, report.dump(2) + "\n");
    std::cerr << "implicitfit fit: " << request.cloud << ": model tree fit failed: " << r.message << "\n";
    return 1;
  }
  Finish(request, r.model, report);
  std::printf("points %zu  inliers %d  rms %.6g  sigma %.6g  normal angle %.3g deg  %.3f s\n", cloud.size(), r.inliers,
              r.rms, r.sigma, r.mean_normal_angle_deg, r.seconds);
  return 0;
}

int RunPatchFit(const ModelFitRequest& request) {
  PatchFitOptions options;
  options.degree = request.degree > 0 ? request.degree : (request.kind == "cubic-patch" ? 3 : 2);
  options.convex = request.convex;
  if (!request.tetrahedron.empty()) {
    if (request.tetrahedron.size() != 12) throw InputError("--tetrahedron takes 12 numbers (4 vertices x y z)");
    try {
      options.tetrahedron = Tetrahedron::FromArray(request.tetrahedron.data());
    } catch (const std::invalid_argument& e) {
      throw InputError(std::string("--tetrahedron: ") + e.what());
    }
    options.has_tetrahedron = true;
  }
  std::string error;
  if (!options.IsValid(&error)) throw InputError(error);
  std::string normals;
  const PointCloud cloud = ReadOrientedCloud(request.cloud, &normals);
  const PatchFitResult r = FitBernsteinPatch(cloud.points, cloud.normals, options);
  const nlohmann::json report = PatchFitReport(r, options, cloud.size(), normals);
  if (!r.success) {
    if (!request.report.empty()) WriteFileAtomically(request.report, report.dump(2) + "\n");
    std::cerr << "implicitfit fit: " << request.cloud << ": patch fit failed: " << r.message << "\n";
    return 1;
  }
  Finish(request, r.ToModel(), report);
  std::printf("points %zu  rms %.6g  normal angle %.3g deg  certified convex %s (min eigenvalue %.3g)", cloud.size(),
              r.rms, r.mean_normal_angle_deg, r.certified_convex ? "yes" : "no", r.min_eigenvalue);
  if (options.convex) std::printf("  unconstrained rms %.6g", r.unconstrained_rms);
  std::printf("  %.3f s\n", r.seconds);
  return 0;
}

}  // namespace implicitfit
