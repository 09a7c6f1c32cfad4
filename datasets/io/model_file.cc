#include "datasets/io/model_file.h"

#include <fstream>
#include <sstream>

#include "datasets/io/atomic_file.h"
#include "datasets/io/io_error.h"
#include "datasets/io/json_file.h"
#include "datasets/io/text_file.h"
#include "model/file/model_json.h"

namespace implicitfit {

Model ReadModelFile(const std::string& path) {
  const std::string text = ReadTextFile(path);
  const nlohmann::json document = ParseJsonDocument(text, path);
  try {
    return ModelFromJson(document);
  } catch (const ModelFormatError& e) {
    throw FileError(path, std::string("invalid model: ") + e.what());
  }
}

void WriteModelFile(const Model& model, const std::string& path) {
  WriteFileAtomically(path, ModelToJson(model).dump(2) + "\n");
}

}  // namespace implicitfit
