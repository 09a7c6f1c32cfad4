#include "fit/fit_report.h"

#include <cmath>
#include <vector>

namespace implicitfit {

nlohmann::json PrimitiveFitReport(const PrimitiveFitResult& r, NodeType kind, size_t points,
                                  const std::string& normals) {
  nlohmann::json j;
  j["success"] = r.success;
  j["message"] = r.message;
  j["points"] = points;
  j["inliers"] = r.inliers.size();
  j["rms_distance"] = r.rms;
  j["max_distance"] = r.max_abs;
  j["sigma"] = r.sigma;
  j["mean_normal_angle_deg"] = r.mean_normal_angle_deg;
  j["iterations"] = r.iterations;
  j["rounds"] = r.rounds;
  j["seconds"] = r.seconds;
  j["normals"] = normals;
  j["estimator"] = EstimatorName(r.estimator);
  j["points_only"] = r.points_only;
  j["form"] = {{"rms", r.form.rms},
               {"min_distance", r.form.min_distance},
               {"max_distance", r.form.max_distance},
               {"form_error", r.form.form_error}};
  if (r.estimator == Estimator::kLeastSquares) j["final_step"] = r.final_step;
  if (r.estimator == Estimator::kMinimumZone) {
    nlohmann::json contacts = nlohmann::json::array();
    for (size_t c = 0; c < r.zone.contacts.size(); ++c)
      contacts.push_back({{"index", r.zone.contacts[c]},
                          {"side", r.zone.sides[c] > 0 ? "outer" : "inner"},
                          {"multiplier", r.zone.multipliers[c]}});
    j["zone"] = {{"width", r.zone.zone_width},
                 {"optimality_verified", r.zone.optimality_verified},
                 {"outer_contacts", r.zone.outer_contacts},
                 {"inner_contacts", r.zone.inner_contacts},
                 {"exchanges", r.zone.exchanges},
                 {"lp_steps", r.zone.iterations},
                 {"kkt_residual", r.zone.kkt_residual},
                 {"contacts", contacts}};
    if (std::isfinite(r.zone.second_order_curvature))
      j["zone"]["second_order_curvature"] = r.zone.second_order_curvature;
  }
  if (!r.parameters.empty()) {
    Model m;
    m.AddPrimitive(kind, r.parameters);
    const std::vector<std::string> names = m.ParameterNames();
    for (size_t i = 0; i < names.size(); ++i) {
      const std::string name = names[i].substr(names[i].find('.') + 1);
      j["parameters"][name] = r.parameters[i];
      if (!r.standard_deviations.empty()) j["standard_deviations"][name] = r.standard_deviations[i];
    }
  }
  return j;
}

nlohmann::json TreeFitReport(const TreeFitResult& r, size_t points, const std::string& normals) {
  nlohmann::json report = {{"success", r.success},
                           {"message", r.message},
                           {"points", points},
                           {"inliers", r.inliers},
                           {"rms_distance", r.rms},
                           {"sigma", r.sigma},
                           {"mean_normal_angle_deg", r.mean_normal_angle_deg},
                           {"iterations", r.iterations},
                           {"seconds", r.seconds},
                           {"normals", normals}};
  const std::vector<std::string> names = r.model.ParameterNames();
  for (size_t i = 0; i < names.size(); ++i)
    report["parameters"][names[i]] = r.model.parameters()[i];
  return report;
}

nlohmann::json PatchFitReport(const PatchFitResult& r, const PatchFitOptions& options,
                              size_t points, const std::string& normals) {
  nlohmann::json report = {{"success", r.success},
                           {"message", r.message},
                           {"points", points},
                           {"degree", options.degree},
                           {"rms_distance", r.rms},
                           {"mean_normal_angle_deg", r.mean_normal_angle_deg},
                           {"mean_normal_cosine", r.mean_normal_cosine},
                           {"convex_constraint", options.convex},
                           {"certified_convex", r.certified_convex},
                           {"min_eigenvalue", r.min_eigenvalue},
                           {"seconds", r.seconds},
                           {"normals", normals}};
  if (options.convex) report["unconstrained_rms_distance"] = r.unconstrained_rms;
  report["termination"] =
      FitTerminationName(r.termination);  // CONVERGENCE, NO_CONVERGENCE, FAILURE
  return report;
}

}  // namespace implicitfit
