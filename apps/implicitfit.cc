// The `implicitfit` command line (docs/cli.md contract). Thin: it wires CLI11 to the commands and
// maps errors to exit codes (2 for invalid usage or input, with the message on stderr).
#include <glog/logging.h>

#include <CLI/CLI.hpp>
#include <cstdlib>
#include <exception>
#include <iostream>
#include <map>
#include <mutex>
#include <string>
#include <vector>

#include "apps/command.h"
#include "apps/command_line_words.h"
#include "apps/option_validators.h"
#include "apps/output_guard.h"
#include "apps/report_header.h"
#include "datasets/clouds/cloud_file.h"
#include "datasets/io/io_error.h"
#include "datasets/io/read_limits.h"
#include "model/file/model_json.h"

#ifndef IMPLICITFIT_VERSION
#define IMPLICITFIT_VERSION "unknown"
#endif

int main(int argc, char** argv) {
  using namespace implicitfit;
  ReopenClosedStandardDescriptors();
  // Ceres logs through glog; its warnings (e.g. the rejected infeasible steps of the convex
  // patch fit) are not for users of the command line.
  FLAGS_minloglevel = google::GLOG_ERROR;
  CLI::App app{"implicitfit: fit implicit surface models to oriented point clouds"};
  app.set_version_flag("--version", "implicitfit " IMPLICITFIT_VERSION);
  app.require_subcommand(1);
  app.fallthrough();  // the limits below may also follow the command's own options
  // Limits (docs/cli.md): on the command line, else from the environment, else the defaults.
  ReadLimits limits;
  unsigned long long max_points = limits.max_points, max_json_mb = limits.max_text_bytes >> 20;
  for (const auto& [variable, value] :
       {std::pair<const char*, unsigned long long*>{"IMPLICITFIT_MAX_POINTS", &max_points},
        {"IMPLICITFIT_MAX_JSON_MB", &max_json_mb}})
    if (const char* text = std::getenv(variable)) {
      if (!StrictNumberProblem(text, true, false).empty() || std::string(text) == "0") {
        std::cerr << "implicitfit: " << variable << "=" << text
                  << ": expected a positive decimal integer\n";
        return 2;
      }
      *value = std::strtoull(text, nullptr, 10);
    }
  app.add_option("--max-points", max_points,
                 "Largest cloud (points of a file, labels, sample --count; default 1e8)")
      ->check(CLI::Range(1ULL, 1ULL << 40))
      ->group("Limits");
  app.add_option("--max-json-mb", max_json_mb,
                 "Largest model or scene file, or manifest, in MiB (default 64)")
      ->check(CLI::Range(1ULL, 1ULL << 20))
      ->group("Limits");

  std::map<std::string, CommandAction> actions;
  actions["fit"] = AddFitCommand(app);
  actions["eval"] = AddEvalCommand(app);
  actions["check"] = AddCheckCommand(app);
  actions["sample"] = AddSampleCommand(app);
  actions["batch"] = AddBatchCommand(app);
  actions["mesh"] = AddMeshCommand(app);
  actions["reconstruct"] = AddReconstructCommand(app);
  actions["detect"] = AddDetectCommand(app);
  actions["design"] = AddDesignCommand(app);
  actions["verify"] = AddVerifyCommand(app);
  actions["view"] = AddViewCommand(app);

  MakeNumberOptionsStrict(app);
  const std::vector<std::string> words(argv + 1, argv + argc);
  if (const std::string problem = UnknownCommandLineWord(app, words); !problem.empty()) {
    std::cerr << problem << "\n";
    return 2;
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    // One line, as every other error of the tool: "implicitfit fit: --out is required; ...".
    const std::string command = CommandName(app, words);
    std::cerr << "implicitfit" << (command.empty() ? "" : " " + command) << ": " << e.what()
              << "; see implicitfit" << (command.empty() ? "" : " " + command) << " --help\n";
    return 2;
  }
  limits.max_points = max_points;
  limits.max_text_bytes = max_json_mb << 20;
  SetReadLimits(limits);
  static std::mutex note_mutex;  // batch reads on several threads
  SetCloudReadObserver([](const std::string& path, const CloudFileInfo& info) {
    if (info.dropped_missing == 0) return;
    std::lock_guard<std::mutex> lock(note_mutex);
    std::cerr << "implicitfit: " << path << ": " << info.dropped_missing << " of "
              << info.records
              << " records dropped (NaN coordinates: no measurement), " << info.records - info.dropped_missing
              << " points kept\n";
  });
  for (auto& [name, action] : actions) {
    if (!app.got_subcommand(name)) continue;
    try {
      SetReportCommand(*app.get_subcommand(name), IMPLICITFIT_VERSION);
      CommandRun run(name, *app.get_subcommand(name));
      return run.Finish(action());
    } catch (const InputError& e) {
      std::cerr << "implicitfit " << name << ": " << e.what() << "\n";
      return 2;
    } catch (const std::exception& e) {
      std::cerr << "implicitfit " << name << ": error: " << e.what() << "\n";
      return 2;
    }
  }
  return 2;
}
