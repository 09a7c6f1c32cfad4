// Public API: the model file (docs/model-file.md's JSON contract, version 1), in memory
// (ModelFromJson / ModelToJson on nlohmann::json, ModelFormatError with the JSON path) and on
// disk (ReadModelFile / WriteModelFile: atomic writes, InputError naming the file).
// Only include/implicitfit/*.h is public API (see implicitfit/model.h).
#pragma once

#include "datasets/io/io_error.h"
#include "datasets/io/model_file.h"
#include "model/file/model_json.h"
