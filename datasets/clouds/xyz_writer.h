// Writes a cloud as plain text "x y z [nx ny nz]" per line, full precision (%.17g), atomically
// (datasets/io/atomic_file.h). The format ParseXyzText reads.
#pragma once

#include <string>

#include "datasets/clouds/point_cloud.h"

namespace implicitfit {

std::string FormatXyz(const PointCloud& cloud);
void WriteXyzFile(const PointCloud& cloud, const std::string& path);

}  // namespace implicitfit
