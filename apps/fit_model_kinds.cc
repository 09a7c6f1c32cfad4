#include "apps/fit_model_kinds.h"

#include <cstdio>
#include <iostream>
#include <nlohmann/json.hpp>

#include "datasets/atomic_file.h"
#include "datasets/io_error.h"
#include "datasets/model_file.h"
#include "datasets/oriented_cloud.h"
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
  nlohmann::json report = {{"success", r.success},   {"message", r.message},   {"points", cloud.size()},
                           {"inliers", r.inliers},   {"rms_distance", r.rms},  {"sigma", r.sigma},
                           {"mean_normal_angle_deg", r.mean_normal_angle_deg}, {"iterations", r.iterations},
                           {"seconds", r.seconds},   {"normals", normals}};
  const std::vector<std::string> names = r.model.ParameterNames();
  for (size_t i = 0; i < names.size(); ++i) report["parameters"][names[i]] = r.model.parameters()[i];
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
  nlohmann::json report = {{"success", r.success},
                           {"message", r.message},
                           {"points", cloud.size()},
                           {"degree", options.degree},
                           {"rms_distance", r.rms},
                           {"mean_normal_angle_deg", r.mean_normal_angle_deg},
                           {"convex_constraint", options.convex},
                           {"certified_convex", r.certified_convex},
                           {"min_eigenvalue", r.min_eigenvalue},
                           {"seconds", r.seconds},
                           {"normals", normals}};
  if (options.convex) report["unconstrained_rms_distance"] = r.unconstrained_rms;
  report["termination"] = FitTerminationName(r.termination);  // CONVERGENCE, NO_CONVERGENCE, FAILURE
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
