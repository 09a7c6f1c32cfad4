#include "fit/common/fit_report.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "fit/bernstein/convex_patch_fit.h"

namespace implicitfit {

namespace {

// snprintf into a std::string.
template <typename... A>
std::string Format(const char* format, A... args) {
  const int n = std::snprintf(nullptr, 0, format, args...);
  std::string out(static_cast<size_t>(std::max(n, 0)) + 1, '\0');
  std::snprintf(out.data(), out.size(), format, args...);
  out.resize(static_cast<size_t>(std::max(n, 0)));
  return out;
}

nlohmann::json PrimitiveJson(const PrimitiveFitResult& r, NodeType kind, size_t points,
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
  j["termination"] = FitTerminationName(r.termination);
  j["estimator"] = EstimatorName(r.estimator);
  j["points_only"] = r.points_only;
  j["form"] = {{"rms", r.form.rms},
               {"min_distance", r.form.min_distance},
               {"max_distance", r.form.max_distance},
               {"form_error", r.form.form_error}};
  if (r.estimator == Estimator::kLeastSquares) j["final_step"] = r.final_step;
  if (r.estimator == Estimator::kMinimumZone) {
    nlohmann::json contacts = nlohmann::json::array();
    for (size_t c = 0; c < r.zone.contacts.size(); ++c) {
      nlohmann::json contact = {{"index", r.zone.contacts[c]},
                                {"side", r.zone.sides[c] > 0 ? "outer" : "inner"},
                                {"multiplier", r.zone.multipliers[c]}};
      if (c < r.zone.contact_points.size()) {
        const Eigen::Vector3d& x = r.zone.contact_points[c];
        contact["point"] = {x.x(), x.y(), x.z()};
        contact["distance"] = r.zone.contact_distances[c];
      }
      contacts.push_back(contact);
    }
    j["zone"] = {{"width", r.zone.zone_width},
                 {"optimality_verified", r.zone.optimality_verified},
                 {"outer_contacts", r.zone.outer_contacts},
                 {"inner_contacts", r.zone.inner_contacts},
                 {"exchanges", r.zone.exchanges},
                 {"lp_steps", r.zone.iterations},
                 {"contact_swaps", r.zone.contact_swaps},
                 {"kkt_residual", r.zone.kkt_residual},
                 {"contacts", contacts}};
    // What the optimality claim rests on (fit/metrology/minimum_zone.h).
    j["zone"]["certificate"] = {
        {"conditions", "first-order Kuhn-Tucker of min t s.t. |d_i| <= t (multipliers by an exact LP)"},
        {"kkt_residual", r.zone.kkt_residual},
        {"kkt_tolerance", kMinimumZoneKktTolerance},
        {"contacts_on_both_faces", r.zone.outer_contacts > 0 && r.zone.inner_contacts > 0},
        {"second_order", std::isfinite(r.zone.second_order_curvature)
                             ? nlohmann::json(r.zone.second_order_curvature >= 0)
                             : nlohmann::json("not needed (k + 1 contacts)")},
        {"verified", r.zone.optimality_verified}};
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

nlohmann::json TreeJson(const TreeFitResult& r, size_t points, const std::string& normals) {
  nlohmann::json report = {{"success", r.success},
                           {"message", r.message},
                           {"points", points},
                           {"inliers", r.inliers},
                           {"rms_distance", r.rms},
                           {"sigma", r.sigma},
                           {"mean_normal_angle_deg", r.mean_normal_angle_deg},
                           {"iterations", r.iterations},
                           {"seconds", r.seconds},
                           {"normals", normals},
                           {"termination", FitTerminationName(r.termination)}};
  const std::vector<std::string> names = r.model.ParameterNames();
  for (size_t i = 0; i < names.size(); ++i)
    report["parameters"][names[i]] = r.model.parameters()[i];
  return report;
}

nlohmann::json PatchJson(const PatchFitResult& r, int degree, bool convex, size_t points,
                         const std::string& normals) {
  nlohmann::json report = {{"success", r.success},
                           {"message", r.message},
                           {"points", points},
                           {"degree", degree},
                           {"rms_distance", r.rms},
                           {"mean_normal_angle_deg", r.mean_normal_angle_deg},
                           {"mean_normal_cosine", r.mean_normal_cosine},
                           {"convex_constraint", convex},
                           {"certified_convex", r.certified_convex},
                           {"min_eigenvalue", r.min_eigenvalue},
                           {"seconds", r.seconds},
                           {"normals", normals}};
  if (convex) {
    report["unconstrained_rms_distance"] = r.unconstrained_rms;
    // The certificate's margin relative to the written control points, and the bound it meets.
    report["margin"] = {{"relative", r.relative_margin},
                        {"required", kConvexRelativeMargin},
                        {"met", r.relative_margin >= kConvexRelativeMargin}};
    report["convex_start"] = r.convex_start;
  }
  report["termination"] =
      FitTerminationName(r.termination);  // CONVERGENCE, NO_CONVERGENCE, FAILURE
  return report;
}

}  // namespace

nlohmann::json PrimitiveFitResult::ToJson(const std::string& normals) const {
  return PrimitiveJson(*this, kind, points, normals);
}

std::string PrimitiveFitResult::BriefReport() const {
  std::string s = Format(
      "points %zu  inliers %zu  rms %.6g  max %.6g  sigma %.6g  normal angle %.3g deg  %.3f s\n",
      points, inliers.size(), rms, max_abs, sigma, mean_normal_angle_deg, seconds);
  s += Format("estimator %s  form error %.6g (min %.6g, max %.6g)", EstimatorName(estimator),
              form.form_error, form.min_distance, form.max_distance);
  if (estimator == Estimator::kMinimumZone)
    s += Format("  zone width %.6g, contacts %d outer / %d inner", zone.zone_width,
                zone.outer_contacts, zone.inner_contacts);
  return s;
}

nlohmann::json TreeFitResult::ToJson(const std::string& normals) const {
  return TreeJson(*this, points, normals);
}

std::string TreeFitResult::BriefReport() const {
  return Format("points %zu  inliers %d  rms %.6g  sigma %.6g  normal angle %.3g deg  %.3f s",
                points, inliers, rms, sigma, mean_normal_angle_deg, seconds);
}

nlohmann::json PatchFitResult::ToJson(const std::string& normals) const {
  return PatchJson(*this, degree, convex_constraint, points, normals);
}

std::string PatchFitResult::BriefReport() const {
  std::string s = Format(
      "points %zu  rms %.6g  normal angle %.3g deg  certified convex %s (min eigenvalue %.3g)",
      points, rms, mean_normal_angle_deg, certified_convex ? "yes" : "no", min_eigenvalue);
  if (convex_constraint)
    s += Format("  relative margin %.3g  unconstrained rms %.6g", relative_margin, unconstrained_rms);
  return s + Format("  %.3f s", seconds);
}

nlohmann::json PrimitiveFitReport(const PrimitiveFitResult& result, NodeType kind, size_t points,
                                  const std::string& normals) {
  return PrimitiveJson(result, kind, points, normals);
}

nlohmann::json TreeFitReport(const TreeFitResult& result, size_t points,
                             const std::string& normals) {
  return TreeJson(result, points, normals);
}

nlohmann::json PatchFitReport(const PatchFitResult& result, const PatchFitOptions& options,
                              size_t points, const std::string& normals) {
  return PatchJson(result, options.degree, options.convex, points, normals);
}

}  // namespace implicitfit
