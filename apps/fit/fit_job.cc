#include "apps/fit/fit_job.h"

#include <sstream>

#include "apps/option_validators.h"
#include "datasets/io/io_error.h"
#include "datasets/normals/normal_trust.h"
#include "datasets/normals/neighbourhoods.h"
#include "fit/common/fit_report.h"
#include "fit/detect/checked_fit.h"

namespace implicitfit {
namespace {

// "radius=2" or "axis=0,0,1" -> {"radius", {2}}.
std::pair<std::string, std::vector<double>> ParseFixOption(const std::string& text) {
  const size_t eq = text.find('=');
  if (eq == std::string::npos || eq == 0)
    throw InputError("--fix " + text + ": expected FIELD=VALUE[,VALUE...]");
  std::vector<double> values;
  std::stringstream s(text.substr(eq + 1));
  std::string item;
  while (std::getline(s, item, ','))  // decimal, finite (apps/option_validators.h)
    values.push_back(ParseDecimal(item, "--fix " + text));
  return {text.substr(0, eq), values};
}

}  // namespace

CloudFit FitCloudFile(const std::string& path, const PrimitiveFitOptions& options) {
  std::string normals;
  Neighbourhoods nb;
  std::vector<Eigen::Vector3d> untrusted;
  const PointCloud cloud = ReadCloudForPrimitiveFit(path, &normals, &nb, &untrusted);
  CloudFit fit;
  fit.points = cloud.size();
  // From points alone, but a volume by the detector's rule: no surface to fit (a fixed
  // --threshold, which says which points are inliers, fits anyway).
  std::string volume;
  if (!untrusted.empty() && options.threshold <= 0 &&
      FillsAVolume(cloud.points, untrusted, nb.indices, nb.spacing, &volume)) {
    fit.result.success = false;
    fit.result.termination = FitTermination::kFailure;
    fit.result.message = std::string("no ") + NodeTypeName(options.kind) +
                         " explains the cloud: " + volume + " (--threshold t fits anyway)";
    fit.report = fit.result.ToJson(normals);
    return fit;
  }
  if (cloud.has_normals() && nb.indices.size() != cloud.size() && cloud.size() >= 2)
    nb = FindNeighbourhoods(cloud.points);
  const CheckedFit checked =
      FitCheckedPrimitive(cloud.points, cloud.normals, nb.indices, nb.spacing, options);
  fit.result = checked.result;
  fit.report = fit.result.ToJson(normals);
  fit.report["check"] = checked.ToJson();
  return fit;
}

PrimitiveFitOptions FitOptionsFromArguments(const std::string& kind, unsigned seed,
                                            double threshold,
                                            const std::vector<std::string>& fixes,
                                            double start_band) {
  PrimitiveFitOptions options;
  if (!FittableKindFromName(kind, &options.kind))
    throw InputError("--model " + kind + ": unknown kind (" + FittableKindNames() + ")");
  options.seed = seed;
  options.threshold = threshold;
  options.start_band = start_band;
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
