// One subcommand of the `implicitfit` tool: it registers its options on a CLI11 subcommand and
// returns the action to run when that subcommand is chosen. The action returns the exit code
// (0 success, 1 negative result, 2 invalid input); library exceptions are mapped to 2 by main.
#pragma once

#include <CLI/CLI.hpp>
#include <functional>

namespace implicitfit {

using CommandAction = std::function<int()>;

CommandAction AddEvalCommand(CLI::App& app);
CommandAction AddCheckCommand(CLI::App& app);
CommandAction AddFitCommand(CLI::App& app);
CommandAction AddSampleCommand(CLI::App& app);
CommandAction AddBatchCommand(CLI::App& app);
CommandAction AddMeshCommand(CLI::App& app);
CommandAction AddReconstructCommand(CLI::App& app);
CommandAction AddDetectCommand(CLI::App& app);
CommandAction AddDesignCommand(CLI::App& app);
CommandAction AddViewCommand(CLI::App& app);

}  // namespace implicitfit
