#include <cstdio>
#include <stdexcept>

#include "implicitfit/patch_mesh.h"

namespace implicitfit {

PatchMeshJobOptions PatchMeshJobOptions::FromCommandLine(int degree, int cells, double cell,
                                                         int continuity, int levels, bool convex) {
  PatchMeshJobOptions options;
  options.fit.degree = degree;
  options.fit.cells = cells;
  options.fit.cell = cell;
  options.fit.continuity = continuity;
  options.fit.convex = convex;
  options.fit.adaptive = levels > 0;
  options.fit.max_levels = levels;
  return options;
}

bool PatchMeshJobOptions::IsValid(std::string* error) const { return fit.IsValid(error); }

nlohmann::json PatchMeshJobOptions::Settings() const {
  return {{"degree", fit.degree},
          {"cells", fit.cells},
          {"cell", fit.cell},
          {"continuity", fit.continuity},
          {"levels", fit.adaptive ? fit.max_levels : 0},
          {"convex", fit.convex}};
}

std::string PatchMeshJobResult::BriefReport() const {
  const MeshFitResult& r = result;
  const BernsteinGrid& g = r.grid;
  char line[512];
  int n = std::snprintf(
      line, sizeof line,
      "points %zu  patches %lld (%dx%dx%d cubes, degree %d, C%d)  rms %.6g  normal angle %.3g deg  "
      "continuity defect %.3g  certified convex on the box %s (%d tetrahedra certified, min "
      "eigenvalue %.3g)  %.3f s",
      points, r.tetrahedra, g.cells[0], g.cells[1], g.cells[2], options.fit.degree,
      options.fit.continuity, r.rms, r.mean_normal_angle_deg, r.continuity_defect,
      r.certified_convex ? "yes" : "no", r.certified_tetrahedra, r.min_eigenvalue, r.seconds);
  if (options.fit.convex && n > 0 && n < static_cast<int>(sizeof line))
    std::snprintf(line + n, sizeof line - n,
                  "\nunconstrained fit (no convexity constraint): rms %.6g", r.unconstrained_rms);
  return line;
}

nlohmann::json PatchMeshJobResult::ToJson(const ReportHeader& header) const {
  const MeshFitResult& r = result;
  const BernsteinGrid& g = r.grid;
  nlohmann::json j = {{"success", success},
                      {"message", message},
                      {"points", points},
                      {"inliers", points},
                      {"degree", options.fit.degree},
                      {"continuity", options.fit.continuity},
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
                      {"convex_constraint", options.fit.convex},
                      {"certified_tetrahedra", r.certified_tetrahedra},
                      {"certified_convex", r.certified_convex},
                      {"min_eigenvalue", r.min_eigenvalue},
                      {"iterations", r.iterations},
                      {"kept_initialisation", r.kept_initialisation},
                      {"box_sign_errors", r.box_sign_errors},
                      {"seconds", r.seconds},
                      {"normals", normals}};
  if (options.fit.adaptive)  // --levels: what the refinement read from the cloud and built
    j["refinement"] = {{"noise", r.noise},
                       {"spacing", r.spacing},
                       {"residual_threshold", r.residual_threshold},
                       {"levels", r.levels},
                       {"leaves", r.leaves},
                       {"sharp_faces", r.sharp_faces},
                       {"rounds", r.rounds},
                       {"rejected_rounds", r.rejected_rounds}};
  return WithJobReportHeader(std::move(j), header, "fit", options.Settings());
}

PatchMeshJobResult FitPatchMeshJob(const std::vector<Eigen::Vector3d>& points,
                                   const std::vector<Eigen::Vector3d>& normals,
                                   const PatchMeshJobOptions& options,
                                   const std::string& normals_action) {
  std::string error;
  if (!options.IsValid(&error)) throw std::invalid_argument(error);
  PatchMeshJobResult out;
  out.options = options;
  out.normals = normals_action;
  out.points = points.size();
  // Normals the reader estimated (datasets/normals/normal_estimation.cc: "estimated, ...") are
  // blends at the creases: their rows are lighter there (MeshFitOptions::normals_estimated).
  MeshFitOptions fit = options.fit;
  fit.normals_estimated = normals_action.rfind("estimated", 0) == 0;
  out.result = FitBernsteinMesh(points, normals, fit);
  out.success = out.result.success;
  out.message = out.result.message;
  out.termination = out.success ? FitTermination::kConverged : FitTermination::kFailure;
  out.seconds = out.result.seconds;
  return out;
}

}  // namespace implicitfit
