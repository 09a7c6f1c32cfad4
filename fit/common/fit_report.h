// The JSON reports of the fits, as `implicitfit fit --report` writes them and the Python module
// returns them (one builder for both, so the two always agree): the results' ToJson(normals)
// (fit/common/fit_summary.h), and these functions, which take the kind, point count, degree and
// convexity flag from their arguments instead of the result. Every report also has
// "termination": CONVERGENCE, NO_CONVERGENCE or FAILURE (fit/common/fit_termination.h). `points` is the
// cloud's size and `normals` says where the normals came from (datasets/normals/oriented_cloud.h, or
// "given").
//   primitive: {"success", "message", "points", "inliers", "rms_distance", "max_distance",
//               "sigma", "mean_normal_angle_deg", "iterations", "rounds", "seconds", "normals",
//               "parameters": {field: value}, "standard_deviations": {field: value}}
//               (field names as Model::ParameterNames without the leading "root.", e.g.
//               "axis[0]", "radius")
//   model tree: {"success", "message", "points", "inliers", "rms_distance", "sigma",
//               "mean_normal_angle_deg", "iterations", "seconds", "normals",
//               "parameters": {Model::ParameterNames: value}}
//   patch:     {"success", "message", "points", "degree", "rms_distance",
//               "mean_normal_angle_deg", "convex_constraint", "certified_convex",
//               "min_eigenvalue", "seconds", "normals"[, "unconstrained_rms_distance"]}
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "fit/bernstein/patch_fitter.h"
#include "fit/primitive/primitive_fitter.h"
#include "fit/tree/tree_fitter.h"

namespace implicitfit {

nlohmann::json PrimitiveFitReport(const PrimitiveFitResult& result, NodeType kind, size_t points,
                                  const std::string& normals);
nlohmann::json TreeFitReport(const TreeFitResult& result, size_t points,
                             const std::string& normals);
nlohmann::json PatchFitReport(const PatchFitResult& result, const PatchFitOptions& options,
                              size_t points, const std::string& normals);

}  // namespace implicitfit
