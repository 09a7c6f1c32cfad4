// Whole-file reading with the checks every reader needs: the path exists, is a regular file
// (not a directory) and can be read. Throws InputError naming the file.
#pragma once

#include <string>

namespace implicitfit {

std::string ReadTextFile(const std::string& path);

}  // namespace implicitfit
