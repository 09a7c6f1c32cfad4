// The header of every JSON report a job builds (docs/cli.md "Reports";
// docs/schemas/report.schema.json), so that a report read months later says what produced it:
//   "format": "implicitfit-report", "format_version": 1,
//   "job": the job ("fit", "detect", "reconstruct", "mesh", "sample", "design", ...),
//   "tool_version": implicitfit's version,
//   "input": {"path": the input, "points": the report's "points", "normals": its "normals"},
//   "settings": every option of the run, given or defaulted, by name (files left out: they are
//              in "input" or are the outputs),
//   "seed": settings["seed"], when the job has one,
//   "units": {"length": "input", "angle": "degree"}: lengths (distances, radii, RMS, tolerances)
//            are in the input's own units, never converted; angles in degrees.
// The keys a report already has are left as they are. The command line fills the settings from
// its parsed options (apps/report_header.h); library callers from their Options.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

namespace implicitfit {

// implicitfit's version ("0.1.0"), as `implicitfit --version` prints it.
std::string ToolVersion();

struct ReportHeader {
  std::string job;                  // empty: "job": null
  std::string tool_version = ToolVersion();
  std::string input;                // the path of the job's input
  nlohmann::json settings = nlohmann::json::object();
};

// `report` (an object; anything else is returned as it is) with the header.
nlohmann::json WithReportHeader(nlohmann::json report, const ReportHeader& header);
// The same for a report whose key order is part of its contract (check --json): the header's
// keys follow the report's own.
nlohmann::ordered_json WithReportHeader(nlohmann::ordered_json report, const ReportHeader& header);
// WithReportHeader for a job's ToJson: what `header` leaves empty (job, input, settings) is the
// job's own.
nlohmann::json WithJobReportHeader(nlohmann::json report, ReportHeader header,
                                   const std::string& job, const nlohmann::json& settings,
                                   const std::string& input = "");

}  // namespace implicitfit
