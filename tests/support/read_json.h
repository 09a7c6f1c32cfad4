// Reads a JSON file the tool wrote (a model, scene or report) for end-to-end tests; a file that
// is missing or not JSON throws nlohmann's parse error, which fails the test with its message.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "support/run_command.h"

namespace testsupport {

inline nlohmann::json ReadJson(const std::string& path) {
  return nlohmann::json::parse(Slurp(path));
}

}  // namespace testsupport
