// Public API: the sample job (`implicitfit sample`, Python's implicitfit.sample) — oriented points
// on a model's zero set with known truth (datasets/generators/model_sampler.h): Gaussian noise
// along the normal, uniform outliers in the box, an optional partial view; the truth labels (the
// leaf primitive each point was drawn on, -1 for outliers and points on no leaf) and, when every
// leaf drawn on is a plane, sphere, cylinder, cone or torus, their kinds (what `detect --truth`
// scores against) (SampleJobOptions with IsValid, SampleModelJob, SampleJobResult with
// BriefReport and ToJson), and the truth-label file writer (datasets/io/truth_labels.h). The
// report:
//   {"success", "message", "points", "normals": "sampled", "outliers", "labelled",
//    "truth_kinds": [kind per leaf] or null, "box": {"min", "max"}, "seconds"} and the header of
//   jobs/report_header.h.
// Only include/implicitfit/*.h is public API (see implicitfit/model.h).
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "datasets/generators/model_sampler.h"
#include "datasets/io/truth_labels.h"
#include "fit/common/fit_summary.h"
#include "jobs/report_header.h"
#include "model/model.h"

namespace implicitfit {

struct SampleJobOptions {
  SampleOptions sample;  // count, noise, outlier fraction, seed, view, box
  // False (with a reason naming the option) for a count below 1, a negative or non-finite
  // noise, an outlier fraction outside [0, 0.99], a view angle outside [0, 180] or a box that
  // is not finite with min < max.
  bool IsValid(std::string* error) const;
  // The "settings" of the report: count, noise, outliers, seed, view, view_angle, box.
  nlohmann::json Settings() const;
};

// success: the zero set was reached inside the box (termination CONVERGENCE), else FAILURE with
// the sampler's reason in message.
struct SampleJobResult : FitSummary {
  SampledCloud sampled;  // the cloud, outlier flags, truth labels, leaf nodes, box
  // The kind of each leaf (Model::nodes order) when the detector knows them all, else empty.
  std::vector<NodeType> truth_kinds;
  // "points N  outliers M  labelled L  s" (one line).
  std::string BriefReport() const;
  // The report above, with `header` (its settings: SampleJobOptions::Settings() when empty).
  nlohmann::json ToJson(const ReportHeader& header = {}) const;
  SampleJobOptions options;  // as given
};

// Throws std::invalid_argument for invalid options.
SampleJobResult SampleModelJob(const Model& model, const SampleJobOptions& options);

}  // namespace implicitfit
