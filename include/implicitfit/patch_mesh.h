// Public API: the patch-mesh job (`implicitfit fit --model patch-mesh`, `batch --model
// patch-mesh`) — a Bernstein mesh, C0 or C1 patches on the Kuhn tetrahedra of a cube grid over
// the cloud's box, fitted to an oriented cloud (fit/bernstein/bernstein_mesh_fitter.h),
// optionally constrained and certified convex on the whole box (PatchMeshJobOptions with
// IsValid, FitPatchMeshJob, PatchMeshJobResult with ToModel, BriefReport and ToJson). The report:
//   {"success", "message", "points", "inliers" (every point), "degree", "continuity",
//    "grid": {"origin", "cell", "cells"}, "patches", "rms_distance", "initial_rms_distance",
//    "unconstrained_rms_distance", "mean_normal_angle_deg", "continuity_defect",
//    "convex_constraint", "certified_tetrahedra", "certified_convex", "min_eigenvalue",
//    "iterations", "kept_initialisation", "box_sign_errors", "seconds", "normals"}, with
//   --levels (MeshFitOptions::adaptive) "refinement": {"noise", "spacing",
//   "residual_threshold", "levels", "leaves", "sharp_faces", "rounds", "rejected_rounds"}, and
//   the header of jobs/report_header.h.
// Only include/implicitfit/*.h is public API (see implicitfit/model.h).
#pragma once

#include <Eigen/Core>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "fit/bernstein/bernstein_mesh_fitter.h"
#include "fit/common/fit_summary.h"
#include "jobs/report_header.h"
#include "model/model.h"

namespace implicitfit {

struct PatchMeshJobOptions {
  // The options of `fit --model patch-mesh --degree k --cells n --cell h --continuity c
  // --levels L [--convex]` (levels > 0: adaptive, at most L levels), the rest the defaults.
  static PatchMeshJobOptions FromCommandLine(int degree, int cells, double cell, int continuity,
                                             int levels, bool convex);
  MeshFitOptions fit;  // degree, cells or cell, continuity, convex, and the fitter's weights
  // MeshFitOptions::IsValid: false (with a reason naming the option) for a degree outside
  // 2..5, a continuity other than 0 or 1, convex without continuity 1, ...
  bool IsValid(std::string* error) const;
  // The "settings" of the report: degree, cells, cell, continuity, levels, convex.
  nlohmann::json Settings() const;
};

// success and message: the fitter's (with convex: also certified on every tetrahedron);
// termination CONVERGENCE on success, else FAILURE.
struct PatchMeshJobResult : FitSummary {
  MeshFitResult result;  // the grid, control points, RMS, certificate figures
  std::string normals;   // where the normals came from
  // The model (one bernstein_mesh node); only on success.
  Model ToModel() const { return result.ToModel(); }
  // "points N  patches P (AxBxC cubes, degree k, C1)  rms ...  s" (one line; with convex a
  // second: the unconstrained fit's rms).
  std::string BriefReport() const;
  // The report above, with `header` (its settings: PatchMeshJobOptions::Settings() when empty).
  nlohmann::json ToJson(const ReportHeader& header = {}) const;
  PatchMeshJobOptions options;  // as given
};

// Throws std::invalid_argument for invalid options. `normals_action` says where the normals
// came from (one per point; a fit without them fails with the reason in message).
PatchMeshJobResult FitPatchMeshJob(const std::vector<Eigen::Vector3d>& points,
                                   const std::vector<Eigen::Vector3d>& normals,
                                   const PatchMeshJobOptions& options,
                                   const std::string& normals_action = "given");

}  // namespace implicitfit
