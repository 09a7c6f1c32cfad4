// Public API: the design job (`implicitfit design`) — Li & Phillips' model from oriented points
// (fit/tree/design_builder.h): m oriented representatives of the cloud (one plane or paraboloid
// each), the model their smooth intersection with an enclosing base (ellipsoid, or a box with the
// convex smoothing); `fit --init` refines it (DesignJobOptions with IsValid, DesignModelJob,
// DesignJobResult with BriefReport and ToJson). The report:
//   {"success", "message", "points", "normals", "primitive", "smoothing", "representatives",
//    "delta", "epsilon", "order" (the blend as built: defaults resolved; epsilon null with the
//    convex smoothing, which has none), "seconds"} and the header of jobs/report_header.h.
// Only include/implicitfit/*.h is public API (see implicitfit/model.h).
#pragma once

#include <Eigen/Core>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "fit/common/fit_summary.h"
#include "fit/tree/design_builder.h"
#include "jobs/report_header.h"
#include "model/model.h"

namespace implicitfit {

struct DesignJobOptions {
  DesignOptions design;  // primitive, count, delta, epsilon, order, smoothing
  // False (with a reason naming the option) for an unknown primitive or smoothing, an epsilon
  // with the convex smoothing or above delta, a count below 1, an order outside 0..14, or a
  // negative or non-finite delta or epsilon.
  bool IsValid(std::string* error) const;
  // The "settings" of the report: primitive, count, delta, epsilon, order, smoothing (as given:
  // 0 for a default).
  nlohmann::json Settings() const;
};

// success: a model was built (termination CONVERGENCE); the job throws otherwise.
struct DesignJobResult : FitSummary {
  Model model;                        // intersection(base, shape_1, ..., shape_m)
  int representatives = 0;            // m
  double delta = 0.0, epsilon = 0.0;  // the blend's, defaults resolved (convex: epsilon = delta)
  std::string normals;                // where the normals came from
  // "N points (X normals), m plane representatives" (one line).
  std::string BriefReport() const;
  // The report above, with `header` (its settings: DesignJobOptions::Settings() when empty).
  nlohmann::json ToJson(const ReportHeader& header = {}) const;
  DesignJobOptions options;  // as given
};

// Throws std::invalid_argument for invalid options, points without one normal each, or fewer
// points than options.design.count. `normals_action` says where the normals came from.
DesignJobResult DesignModelJob(const std::vector<Eigen::Vector3d>& points,
                               const std::vector<Eigen::Vector3d>& normals,
                               const DesignJobOptions& options,
                               const std::string& normals_action = "given");

}  // namespace implicitfit
