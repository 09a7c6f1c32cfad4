// Placeholder for a contract command whose issue is still open: it parses nothing and exits 2
// with "not yet available" rather than producing a fake result.
#include <iostream>

#include "apps/command.h"

namespace implicitfit {

CommandAction AddNotYetAvailableCommand(CLI::App& app, const std::string& name,
                                        const std::string& description) {
  auto* cmd = app.add_subcommand(name, description + " (not yet available)");
  cmd->allow_extras();
  return [name]() {
    std::cerr << "implicitfit " << name << ": not yet available in this version\n";
    return 2;
  };
}

}  // namespace implicitfit
