#include "jobs/report_header.h"

#include <utility>

#ifndef IMPLICITFIT_VERSION
#define IMPLICITFIT_VERSION "unknown"
#endif

namespace implicitfit {
namespace {

template <typename Json>
Json AddHeader(Json report, const ReportHeader& h) {
  if (!report.is_object()) return report;
  const auto set = [&](const char* key, const Json& value) {
    if (!report.contains(key)) report[key] = value;
  };
  set("format", "implicitfit-report");
  set("format_version", 1);
  set("job", h.job.empty() ? Json(nullptr) : Json(h.job));
  set("tool_version", h.tool_version);
  Json in = Json::object();
  in["path"] = h.input;
  in["points"] = report.contains("points") ? report["points"] : Json(nullptr);
  in["normals"] = report.contains("normals") ? report["normals"] : Json(nullptr);
  set("input", in);
  set("settings", Json(h.settings));
  if (h.settings.contains("seed")) set("seed", Json(h.settings["seed"]));
  Json units = Json::object();
  units["length"] = "input";
  units["angle"] = "degree";
  set("units", units);
  return report;
}

}  // namespace

std::string ToolVersion() { return IMPLICITFIT_VERSION; }

nlohmann::json WithReportHeader(nlohmann::json report, const ReportHeader& header) {
  return AddHeader(std::move(report), header);
}

nlohmann::ordered_json WithReportHeader(nlohmann::ordered_json report,
                                        const ReportHeader& header) {
  return AddHeader(std::move(report), header);
}

nlohmann::json WithJobReportHeader(nlohmann::json report, ReportHeader header,
                                   const std::string& job, const nlohmann::json& settings,
                                   const std::string& input) {
  if (header.job.empty()) header.job = job;
  if (header.input.empty()) header.input = input;
  if (header.settings.empty()) header.settings = settings;
  return AddHeader(std::move(report), header);
}

}  // namespace implicitfit
