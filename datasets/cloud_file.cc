#include "datasets/cloud_file.h"

#include <algorithm>
#include <cctype>

#include "datasets/io_error.h"
#include "datasets/xyz_reader.h"

namespace implicitfit {

PointCloud ReadCloudFile(const std::string& path) {
  const size_t dot = path.find_last_of('.');
  std::string ext = dot == std::string::npos ? "" : path.substr(dot + 1);
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  if (ext == "xyz" || ext == "pwn" || ext == "txt") return ReadXyzFile(path);
  throw FileError(path, "unsupported cloud format '." + ext + "' (supported: .xyz .pwn .txt)");
}

}  // namespace implicitfit
