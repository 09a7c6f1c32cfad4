#include <chrono>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "implicitfit/design.h"
#include "model/blends/unit_step.h"

namespace implicitfit {

bool DesignJobOptions::IsValid(std::string* error) const {
  const DesignOptions& d = design;
  std::string problem;
  if (!IsDesignPrimitive(d.primitive))
    problem = "primitive '" + d.primitive + "': expected plane or paraboloid";
  else if (!IsDesignSmoothing(d.smoothing))
    problem = "smoothing '" + d.smoothing + "': expected li-phillips or convex";
  else if (d.count < 1)
    problem = "count: must be at least 1";
  else if (d.order < 0 || d.order > UnitStep::kMaxOrder)
    problem = "order: must be in 0.." + std::to_string(UnitStep::kMaxOrder);
  else if (!std::isfinite(d.delta) || d.delta < 0)
    problem = "delta: must be >= 0 (0: 2% of the bounding-box diagonal)";
  else if (!std::isfinite(d.epsilon) || d.epsilon < 0)
    problem = "epsilon: must be >= 0 (0: delta / 2)";
  else if (d.smoothing == "convex" && d.epsilon > 0)
    problem = "epsilon: a convex-smoothing blend has none (its width is delta)";
  else if (d.delta > 0 && d.epsilon > d.delta)
    problem = "epsilon: must not exceed delta";
  if (!problem.empty()) *error = problem;
  return problem.empty();
}

nlohmann::json DesignJobOptions::Settings() const {
  const DesignOptions& d = design;
  return {{"primitive", d.primitive}, {"count", d.count}, {"delta", d.delta},
          {"epsilon", d.epsilon},     {"order", d.order}, {"smoothing", d.smoothing}};
}

std::string DesignJobResult::BriefReport() const {
  char line[200];
  std::snprintf(line, sizeof line, "%zu points (%s normals), %d %s representatives", points,
                normals.c_str(), representatives, options.design.primitive.c_str());
  return line;
}

nlohmann::json DesignJobResult::ToJson(const ReportHeader& header) const {
  const DesignOptions& d = options.design;
  nlohmann::json j = {
      {"success", success},
      {"message", message},
      {"points", points},
      {"normals", normals},
      {"primitive", d.primitive},
      {"smoothing", d.smoothing},
      {"representatives", representatives},
      {"delta", delta},
      {"epsilon", d.smoothing == "convex" ? nlohmann::json(nullptr) : nlohmann::json(epsilon)},
      {"order", d.order},
      {"seconds", seconds}};
  return WithJobReportHeader(std::move(j), header, "design", options.Settings());
}

DesignJobResult DesignModelJob(const std::vector<Eigen::Vector3d>& points,
                               const std::vector<Eigen::Vector3d>& normals,
                               const DesignJobOptions& options, const std::string& normals_action) {
  const auto start = std::chrono::steady_clock::now();
  std::string error;
  if (!options.IsValid(&error)) throw std::invalid_argument(error);
  if (normals.size() != points.size())
    throw std::invalid_argument("a design needs one normal per point");
  if (static_cast<long long>(points.size()) < options.design.count)
    throw std::invalid_argument(std::to_string(points.size()) + " points, fewer than count " +
                                std::to_string(options.design.count));
  DesignJobResult out;
  out.options = options;
  out.normals = normals_action;
  out.points = points.size();
  out.model = DesignFromOrientedPoints(points, normals, options.design);
  // intersection(base, shape_1, ..., shape_m): the root's children after the base.
  const ModelNode& root = out.model.nodes()[out.model.root()];
  out.representatives = static_cast<int>(root.children.size()) - 1;
  out.delta = out.model.parameters()[root.first_parameter];
  out.epsilon = out.model.parameters()[root.first_parameter + 1];
  out.success = true;
  out.termination = FitTermination::kConverged;
  out.message = "designed";
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

}  // namespace implicitfit
