#include "apps/fit_job.h"

#include <sstream>

#include "datasets/normal_trust.h"
#include "datasets/io_error.h"
#include "model/model.h"

namespace implicitfit {
namespace {

nlohmann::json Report(const PrimitiveFitResult& r, NodeType kind, size_t points, const std::string& normals) {
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
      contacts.push_back({{"index", r.zone.contacts[c]}, {"side", r.zone.sides[c] > 0 ? "outer" : "inner"},
                          {"multiplier", r.zone.multipliers[c]}});
    j["zone"] = {{"width", r.zone.zone_width},
                 {"optimality_verified", r.zone.optimality_verified},
                 {"outer_contacts", r.zone.outer_contacts},
                 {"inner_contacts", r.zone.inner_contacts},
                 {"exchanges", r.zone.exchanges},
                 {"contacts", contacts}};
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

// "radius=2" or "axis=0,0,1" -> {"radius", {2}}.
std::pair<std::string, std::vector<double>> ParseFixOption(const std::string& text) {
  const size_t eq = text.find('=');
  if (eq == std::string::npos || eq == 0) throw InputError("--fix " + text + ": expected FIELD=VALUE[,VALUE...]");
  std::vector<double> values;
  std::stringstream s(text.substr(eq + 1));
  std::string item;
  while (std::getline(s, item, ',')) {
    try {
      size_t used = 0;
      values.push_back(std::stod(item, &used));
      if (used != item.size()) throw std::invalid_argument(item);
    } catch (const std::exception&) {
      throw InputError("--fix " + text + ": '" + item + "' is not a number");
    }
  }
  return {text.substr(0, eq), values};
}

}  // namespace

CloudFit FitCloudFile(const std::string& path, const PrimitiveFitOptions& options) {
  std::string normals;
  const PointCloud cloud = ReadCloudForPrimitiveFit(path, &normals);
  CloudFit fit;
  fit.points = cloud.size();
  fit.result = FitPrimitive(cloud.points, cloud.normals, options);
  fit.report = Report(fit.result, options.kind, cloud.size(), normals);
  return fit;
}

PrimitiveFitOptions FitOptionsFromArguments(const std::string& kind, unsigned seed, double threshold,
                                            const std::vector<std::string>& fixes) {
  PrimitiveFitOptions options;
  if (!FittableKindFromName(kind, &options.kind))
    throw InputError("--model " + kind + ": unknown kind (plane, sphere, cylinder, cone, torus)");
  options.seed = seed;
  options.threshold = threshold;
  for (const std::string& f : fixes) options.fixed.insert(ParseFixOption(f));
  std::string error;
  if (!options.IsValid(&error)) throw InputError(error);
  return options;
}

void SetEstimatorFromArgument(const std::string& name, PrimitiveFitOptions* options) {
  if (!EstimatorFromName(name, &options->estimator))
    throw InputError("--estimator " + name + ": unknown (robust, least-squares, minimum-zone)");
}

}  // namespace implicitfit
