// The fit of one cloud file, shared by the `fit` and `batch` commands: read the cloud
// (datasets/clouds/cloud_file.h), fit one primitive and check that it is real
// (fit/detect/checked_fit.h: on a cloud of many surfaces a real primitive of the kind or a
// failure, never a confident wrong one) and build the JSON report that `fit --report` writes
// (its "check" field: fit/detect/checked_fit.h):
//   {"success", "message", "points", "inliers", "rms_distance", "max_distance", "sigma",
//    "mean_normal_angle_deg", "iterations", "rounds", "seconds", "normals",
//    "parameters": {field: value}, "standard_deviations": {field: value},
//    "estimator", "points_only", "form": {"rms", "min_distance", "max_distance", "form_error"},
//    least-squares: "final_step"; minimum-zone: "zone": {"width", "optimality_verified",
//    "outer_contacts", "inner_contacts", "contacts": [{"index", "side", "multiplier"}]}}
// Clouds without trustworthy normals are fitted from points alone (datasets/normals/normal_trust.h).
// Writing the files is left to the commands.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "fit/primitive/primitive_fitter.h"

namespace implicitfit {

struct CloudFit {
  size_t points = 0;          // points read from the file
  PrimitiveFitResult result;  // result.success false: a negative result (no model)
  nlohmann::json report;      // the report of the fit, success or not
};

// Throws InputError (naming the file) when the cloud cannot be read.
CloudFit FitCloudFile(const std::string& path, const PrimitiveFitOptions& options);

// The fit options of the command-line arguments --model KIND, --seed, --threshold (a fixed
// inlier distance; <= 0: none), --fix FIELD=V[,V...] (e.g. "radius=2", "axis=0,0,1") and --band
// (the adaptive band's start; <= 0: from the cloud); InputError when invalid.
PrimitiveFitOptions FitOptionsFromArguments(const std::string& kind, unsigned seed,
                                            double threshold,
                                            const std::vector<std::string>& fixes,
                                            double start_band = 0.0);

// --estimator robust|least-squares|minimum-zone into options; InputError for another name.
void SetEstimatorFromArgument(const std::string& name, PrimitiveFitOptions* options);

}  // namespace implicitfit
