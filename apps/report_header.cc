#include "apps/report_header.h"

#include <mutex>
#include <utility>
#include <vector>

#include "apps/option_validators.h"
#include "apps/output_guard.h"
#include "datasets/clouds/cloud_file.h"
#include "datasets/io/atomic_file.h"

namespace implicitfit {
namespace {

struct ReportCommand {
  std::string job, tool_version, input;
  nlohmann::json settings = nlohmann::json::object();
};

ReportCommand& Current() {
  static ReportCommand command;
  return command;
}

// A command-line value as JSON: numbers as numbers (the strict decimal form every numeric
// option takes), the rest as strings.
nlohmann::json ValueOf(const std::string& text) {
  if (!text.empty() && StrictNumberProblem(text, false, true).empty()) {
    if (StrictNumberProblem(text, true, true).empty()) {
      try {
        return std::stoll(text);
      } catch (const std::out_of_range&) {
      }
    }
    return std::stod(text);
  }
  return text;
}

void AddOptions(CLI::App& command, const CommandFiles& files, nlohmann::json* settings) {
  for (CLI::Option* option : command.get_options()) {
    const std::string name = option->get_single_name();
    if (name == "help" || name == "help-all" || name == "version" || !option->nonpositional())
      continue;
    bool is_file = false;
    for (const std::string& value : option->results())
      for (const auto* list : {&files.inputs, &files.outputs})
        for (const std::string& file : *list) is_file = is_file || file == value;
    if (is_file) continue;
    if (option->get_items_expected_max() == 0) {  // a flag
      (*settings)[name] = option->count() > 0;
      continue;
    }
    std::vector<std::string> values = option->results();
    const bool list = option->get_items_expected_max() > 1;
    if (values.empty()) {
      // Not given: the value its variable holds after parsing, which is the default (an
      // option without one, e.g. an optional file, is left out).
      option->capture_default_str();
      const std::string value = option->get_default_str();
      if (value == "[]") {
        (*settings)[name] = nlohmann::json::array();
        continue;
      }
      if (value.empty()) continue;
      values = {value};
    }
    if (values.size() == 1 && !list) {
      (*settings)[name] = ValueOf(values[0]);
    } else {
      nlohmann::json list = nlohmann::json::array();
      for (const std::string& v : values) list.push_back(ValueOf(v));
      (*settings)[name] = list;
    }
  }
}

}  // namespace

namespace {

nlohmann::json SettingsOf(CLI::App& command, const CommandFiles& files) {
  nlohmann::json settings = nlohmann::json::object();
  AddOptions(command, files, &settings);
  if (CLI::App* tool = command.get_parent()) AddOptions(*tool, files, &settings);
  return settings;
}

}  // namespace

nlohmann::json CommandSettings(CLI::App& command) {
  return SettingsOf(command, FilesOfCommand(command));
}

void SetReportCommand(CLI::App& command, const std::string& tool_version) {
  ReportCommand& c = Current();
  c.job = command.get_name();
  c.tool_version = tool_version;
  const CommandFiles files = FilesOfCommand(command);
  c.settings = SettingsOf(command, files);
  c.input.clear();
  for (const std::string& file : files.inputs)
    if (c.input.empty() && IsCloudFileName(file)) c.input = file;
  if (c.input.empty() && !files.inputs.empty()) c.input = files.inputs.front();
}

ReportHeader CommandReportHeader(const std::string& input) {
  const ReportCommand& c = Current();
  ReportHeader header;
  header.job = c.job;
  header.tool_version = c.tool_version;
  header.input = input.empty() ? c.input : input;
  header.settings = c.settings;
  return header;
}

nlohmann::json WithReportHeader(nlohmann::json report, const std::string& input) {
  return WithReportHeader(std::move(report), CommandReportHeader(input));
}

nlohmann::ordered_json WithReportHeader(nlohmann::ordered_json report, const std::string& input) {
  return WithReportHeader(std::move(report), CommandReportHeader(input));
}

void WriteReportFile(const std::string& path, const nlohmann::json& report,
                     const std::string& input) {
  WriteFileAtomically(path, WithReportHeader(report, input).dump(2) + "\n");
}

}  // namespace implicitfit
