// The `implicitfit` command line (docs/cli.md contract). Thin: it wires CLI11 to the commands and
// maps errors to exit codes (2 for invalid usage or input, with the message on stderr).
#include <glog/logging.h>

#include <CLI/CLI.hpp>
#include <exception>
#include <iostream>
#include <map>

#include "apps/command.h"
#include "datasets/io/io_error.h"
#include "model/file/model_json.h"

#ifndef IMPLICITFIT_VERSION
#define IMPLICITFIT_VERSION "unknown"
#endif

int main(int argc, char** argv) {
  using namespace implicitfit;
  // Ceres logs through glog; its warnings (e.g. the rejected infeasible steps of the convex
  // patch fit) are not for users of the command line.
  FLAGS_minloglevel = google::GLOG_ERROR;
  CLI::App app{"implicitfit: fit implicit surface models to oriented point clouds"};
  app.set_version_flag("--version", "implicitfit " IMPLICITFIT_VERSION);
  app.require_subcommand(1);

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
  actions["view"] = AddViewCommand(app);

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    app.exit(e);  // prints the message
    return 2;
  }
  for (auto& [name, action] : actions) {
    if (!app.got_subcommand(name)) continue;
    try {
      return action();
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
