// Model files on disk (the JSON contract of docs/model-file.md, parsed by model/file/model_json).
// ReadModelFile throws InputError "<file>: <problem>" (for malformed JSON, with the line and
// column nlohmann reports); WriteModelFile writes atomically (pretty-printed, 2 spaces).
#pragma once

#include <string>

#include "model/model.h"

namespace implicitfit {

Model ReadModelFile(const std::string& path);
void WriteModelFile(const Model& model, const std::string& path);

}  // namespace implicitfit
