// Errors of reading or writing user files. The message always starts with the file name and,
// for text formats, the 1-based line: "cloud.xyz:17: expected 3 or 6 numbers, found 2".
// The command line maps InputError to exit code 2.
#pragma once

#include <stdexcept>
#include <string>

namespace implicitfit {

class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

inline InputError FileError(const std::string& file, const std::string& problem) {
  return InputError(file + ": " + problem);
}
inline InputError LineError(const std::string& file, long line, const std::string& problem) {
  return InputError(file + ":" + std::to_string(line) + ": " + problem);
}

}  // namespace implicitfit
