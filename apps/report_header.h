// The header of every JSON report the command line writes (docs/cli.md "Reports";
// docs/schemas/report.schema.json), so that a report read months later says what produced it:
//   "format": "implicitfit-report", "format_version": 1,
//   "job": the command ("fit", "detect", "reconstruct", "verify", "batch", ...),
//   "tool_version": implicitfit's version,
//   "input": {"path": the cloud, "points": its points, "normals": where its normals came from},
//   "settings": every option of the run, given or defaulted, by name without the dashes
//              (files the run reads or writes left out: they are in "input" or are the outputs),
//   "seed": the run's random seed, when the command has one (also in "settings"),
//   "units": {"length": "input", "angle": "degree"}: lengths (distances, radii, RMS, tolerances)
//            are in the cloud's own units, never converted; angles in degrees.
// The keys a report already has are left as they are.
#pragma once

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>
#include <string>

namespace implicitfit {

// Remembers the command being run (its name, settings and input); main calls it once, after
// parsing.
void SetReportCommand(CLI::App& command, const std::string& tool_version);

// `report` with the header; `input` is the cloud the report is about (batch: each input), or ""
// for the command's own cloud argument.
nlohmann::json WithReportHeader(nlohmann::json report, const std::string& input = "");
// The same for a report whose key order is part of its contract (check --json): the header's
// keys follow the report's own.
nlohmann::ordered_json WithReportHeader(nlohmann::ordered_json report,
                                        const std::string& input = "");

// WriteFileAtomically(path, WithReportHeader(report, input), indented).
void WriteReportFile(const std::string& path, const nlohmann::json& report,
                     const std::string& input = "");

// The settings object of the header, from the options of `command` (and of its parent: the
// tool's limits), after parsing. Non-const: an option not given is read from its variable
// (CLI11's capture_default_str).
nlohmann::json CommandSettings(CLI::App& command);

}  // namespace implicitfit
