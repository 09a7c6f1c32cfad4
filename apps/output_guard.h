// File safety of every command (docs/cli.md, "File safety"), in one place so that commands
// stay thin: which options name files a command reads and files it writes, and the checks that
// run after parsing and before the command does any work:
//   - each output resolved (datasets/io/output_path.h: symbolic links followed; a directory,
//     device node, FIFO or socket refused unless it is "-", standard output), its folder probed
//     (a missing or unwritable folder fails at once, not after the fit);
//   - an output equal to an input, or to another output (same inode, or the same normalised
//     path), refused;
//   - temporaries that killed runs left in the outputs' folders removed.
// Outputs and inputs: a table per command in output_guard.cc (fit: --out --report --view --ply,
// input --init; detect: --out --labels --ply --report --view; reconstruct: --out --mesh --report
// --view, input --scene; view: --out --png, input --labels; ...), every positional argument an
// input; a command not in the table: --out and --report. A command may also mark an option with
// OutputFileOption or InputFileOption (the mark wins).
// CommandRun then makes the run all or nothing (datasets/io/atomic_file.h OutputTransaction:
// outputs are renamed into place only when the command returns; an exception leaves none) and
// treats a failed write to standard output (full disk, closed descriptor) as an error. Commands
// that write as they go get the checks without the transaction (view: --png screenshots the
// page just written); batch (its outputs must survive a kill, --resume continues) guards its
// own files (apps/batch/batch_command.cc).
#pragma once

#include <CLI/CLI.hpp>
#include <memory>
#include <string>
#include <vector>

namespace implicitfit {

CLI::Option* OutputFileOption(CLI::Option* option);
CLI::Option* InputFileOption(CLI::Option* option);

struct CommandFiles {
  std::vector<std::string> inputs, outputs;
};
CommandFiles FilesOfCommand(const CLI::App& command);

// Throws InputError naming the file (see the header comment).
void GuardOutputs(const CommandFiles& files);

// Inputs `inputs` and outputs `outputs` must be different files (InputError naming both).
void RefuseOverlaps(const std::vector<std::string>& inputs,
                    const std::vector<std::string>& outputs);

bool GuardsItsOwnFiles(const std::string& name);
bool WritesAsItGoes(const std::string& name);

// Standard descriptors 0, 1, 2 that the caller closed are reopened on /dev/null (read-only for
// stdout, so that writes fail): a file the command opens can never become its stdout.
void ReopenClosedStandardDescriptors();

// One command run: construct after parsing (guards the files, opens the transaction unless the
// command writes as it goes), call Finish(exit code) after the action returned; destroyed
// without Finish (an exception), it discards every output.
class CommandRun {
 public:
  CommandRun(const std::string& name, const CLI::App& command);
  ~CommandRun();
  // Flushes standard output (InputError when that fails), then commits the outputs.
  int Finish(int exit_code);

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace implicitfit
