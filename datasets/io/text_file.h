// Whole-file reading of small text files (models, scenes, manifests) with the checks every
// reader needs: the path exists and is a regular file (datasets/io/input_file.h: no directory,
// FIFO or device), it can be read, and it is at most CurrentReadLimits().max_text_bytes
// (datasets/io/read_limits.h). Throws InputError naming the file.
#pragma once

#include <string>

namespace implicitfit {

std::string ReadTextFile(const std::string& path);

}  // namespace implicitfit
