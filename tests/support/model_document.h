// A model file around one root node written as JSON text: the document's text (for the command
// line) or the loaded model (model/file/model_json.h; a bad node throws ModelFormatError).
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "model/file/model_json.h"
#include "model/model.h"

namespace testsupport {

inline std::string ModelDocument(const std::string& root) {
  return R"({"format": "implicitfit-model", "version": 1, "root": )" + root + "}";
}

inline implicitfit::Model ModelFromRoot(const std::string& root) {
  return implicitfit::ModelFromJson(nlohmann::json::parse(ModelDocument(root)));
}

}  // namespace testsupport
