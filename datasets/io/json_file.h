// Strict JSON documents (model files, scene files): nlohmann's parser, plus the refusal of
// duplicate keys, which it accepts silently (the last one wins: {"radius": 1, "radius": -5}
// would be read as -5 with no word). Errors are InputError "<file>: invalid JSON: ..." with the
// line and column nlohmann reports, or "duplicate key \"k\" in <JSON path>".
#pragma once

#include <nlohmann/json.hpp>
#include <string>

namespace implicitfit {

nlohmann::json ParseJsonDocument(const std::string& text, const std::string& path);

}  // namespace implicitfit
