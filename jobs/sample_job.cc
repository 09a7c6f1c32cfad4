#include <chrono>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "implicitfit/sample.h"

namespace implicitfit {
namespace {

nlohmann::json VectorJson(const Eigen::Vector3d& v) { return {v.x(), v.y(), v.z()}; }

bool DetectorKnows(NodeType k) {
  return k == NodeType::kPlane || k == NodeType::kSphere || k == NodeType::kCylinder ||
         k == NodeType::kCone || k == NodeType::kTorus;
}

// The kinds of the leaves, or none when a point lies on a leaf the detector does not know.
std::vector<NodeType> TruthKinds(const Model& model, const SampledCloud& sampled) {
  std::vector<NodeType> kinds;
  for (int node : sampled.leaf_nodes) kinds.push_back(model.nodes()[node].type);
  for (int l : sampled.primitive)
    if (l >= 0 && !DetectorKnows(kinds[l])) return {};
  return kinds;
}

}  // namespace

bool SampleJobOptions::IsValid(std::string* error) const {
  const SampleOptions& s = sample;
  const char* problem = nullptr;
  if (s.count < 1) problem = "count: must be at least 1";
  else if (!std::isfinite(s.noise) || s.noise < 0) problem = "noise: must be >= 0";
  else if (!(s.outlier_fraction >= 0 && s.outlier_fraction <= 0.99))
    problem = "outliers: must be in [0, 0.99]";
  else if (!(s.view_angle_deg >= 0 && s.view_angle_deg <= 180))
    problem = "view_angle: must be in [0, 180] degrees";
  else if (!s.view_dir.allFinite()) problem = "view: must be finite";
  else if (s.has_box && (!s.box_min.allFinite() || !s.box_max.allFinite() ||
                         !((s.box_max - s.box_min).array() > 0).all()))
    problem = "box: needs xmin < xmax, ymin < ymax, zmin < zmax (finite)";
  if (problem != nullptr) *error = problem;
  return problem == nullptr;
}

nlohmann::json SampleJobOptions::Settings() const {
  const SampleOptions& s = sample;
  nlohmann::json box = nullptr;
  if (s.has_box) box = {{"min", VectorJson(s.box_min)}, {"max", VectorJson(s.box_max)}};
  return {{"count", s.count},           {"noise", s.noise},
          {"outliers", s.outlier_fraction}, {"seed", s.seed},
          {"view", s.view_dir.isZero() ? nlohmann::json(nullptr) : VectorJson(s.view_dir)},
          {"view_angle", s.view_angle_deg}, {"box", box}};
}

std::string SampleJobResult::BriefReport() const {
  size_t outliers = 0, labelled = 0;
  for (bool o : sampled.is_outlier) outliers += o;
  for (int l : sampled.primitive) labelled += l >= 0;
  char line[160];
  std::snprintf(line, sizeof line, "points %zu  outliers %zu  labelled %zu  %.3f s", points,
                outliers, labelled, seconds);
  return line;
}

nlohmann::json SampleJobResult::ToJson(const ReportHeader& header) const {
  size_t outliers = 0, labelled = 0;
  for (bool o : sampled.is_outlier) outliers += o;
  for (int l : sampled.primitive) labelled += l >= 0;
  nlohmann::json kinds = nullptr;
  if (!truth_kinds.empty()) {
    kinds = nlohmann::json::array();
    for (NodeType k : truth_kinds) kinds.push_back(NodeTypeName(k));
  }
  nlohmann::json j = {{"success", success},
                      {"message", message},
                      {"points", points},
                      {"normals", "sampled"},
                      {"outliers", outliers},
                      {"labelled", labelled},
                      {"truth_kinds", kinds},
                      {"box", {{"min", VectorJson(sampled.box_min)},
                               {"max", VectorJson(sampled.box_max)}}},
                      {"seconds", seconds}};
  return WithJobReportHeader(std::move(j), header, "sample", options.Settings());
}

SampleJobResult SampleModelJob(const Model& model, const SampleJobOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  std::string error;
  if (!options.IsValid(&error)) throw std::invalid_argument(error);
  SampleJobResult out;
  out.options = options;
  try {
    out.sampled = SampleModel(model, options.sample);
    out.truth_kinds = TruthKinds(model, out.sampled);
    out.success = true;
    out.termination = FitTermination::kConverged;
    out.message = "sampled";
  } catch (const std::runtime_error& e) {
    out.message = e.what();
  }
  out.points = out.sampled.cloud.size();
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

}  // namespace implicitfit
