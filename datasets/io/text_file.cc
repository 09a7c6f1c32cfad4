#include "datasets/io/text_file.h"

#include "datasets/io/input_file.h"
#include "datasets/io/read_limits.h"

namespace implicitfit {

std::string ReadTextFile(const std::string& path) {
  InputFile file(path);
  return file.ReadAll(CurrentReadLimits().max_text_bytes, "--max-json-mb");
}

}  // namespace implicitfit
