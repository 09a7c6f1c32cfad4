// The command line's side of the report header (jobs/report_header.h builds it): the job is the
// command, the input its cloud argument (else its first input file) and the settings every
// option of the run, given or defaulted, by name without the dashes (files the run reads or
// writes left out).
#pragma once

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>
#include <string>

#include "jobs/report_header.h"

namespace implicitfit {

// The header of the command being run (after SetReportCommand); `input` as below.
ReportHeader CommandReportHeader(const std::string& input = "");

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
