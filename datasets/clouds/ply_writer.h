// PLY output of a cloud: "element vertex N" with x y z, then nx ny nz when the cloud has
// normals, then an optional per-point int "label" (PlyWriteOptions::labels, e.g. the
// primitive of each point in a detected scene) and an optional per-point scalar "residual" (e.g.
// the fitted model's f at each point, so CloudCompare or MeshLab can colour the cloud by it).
// Binary little endian by default, ASCII on request; double by default (the fit works in double),
// float to halve big files. Written atomically (atomic_file.h): the file is complete or absent.
// Throws InputError "<file>: cannot write: ..." on I/O failure and std::invalid_argument when the
// residuals do not match the points or a value to write is NaN or infinite.
#pragma once

#include <string>
#include <vector>

#include "datasets/clouds/point_cloud.h"

namespace implicitfit {

struct PlyWriteOptions {
  bool ascii = false;       // false: binary_little_endian
  bool single = false;      // float instead of double properties
  std::vector<int> labels;  // empty, or one per point: an int property "label" before "residual"
};

void WritePlyFile(const PointCloud& cloud, const std::string& path,
                  const std::vector<double>& residuals = {}, const PlyWriteOptions& options = {});

}  // namespace implicitfit
