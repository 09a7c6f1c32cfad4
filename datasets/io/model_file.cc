#include "datasets/io/model_file.h"

#include <fstream>
#include <sstream>

#include "datasets/io/atomic_file.h"
#include "datasets/io/io_error.h"
#include "datasets/io/text_file.h"
#include "model/file/model_json.h"

namespace implicitfit {

Model ReadModelFile(const std::string& path) {
  const std::string text = ReadTextFile(path);
  nlohmann::json document;
  try {
    document = nlohmann::json::parse(text);
  } catch (const nlohmann::json::exception& e) {
    // e.what() reads "[json.exception.parse_error.101] parse error at line L, column C: ..."
    // or, for a number beyond the double range (found by the model fuzzer),
    // "[json.exception.out_of_range.406] number overflow parsing '1e3081'".
    std::string what = e.what();
    const size_t at = what.find("] ");
    throw FileError(path,
                    "invalid JSON: " + (at == std::string::npos ? what : what.substr(at + 2)));
  }
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
