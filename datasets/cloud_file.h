// Reads any supported cloud by its extension: .xyz/.pwn/.txt (plain text). Other extensions
// are refused with InputError naming the file and the supported list.
#pragma once

#include <string>

#include "datasets/point_cloud.h"

namespace implicitfit {

PointCloud ReadCloudFile(const std::string& path);

}  // namespace implicitfit
