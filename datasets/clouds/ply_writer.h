// PLY output of a cloud: "element vertex N" with x y z, then nx ny nz when the cloud has
// normals, then optional per-point uchar "red green blue" (PlyWriteOptions::colours), an int
// "label" (PlyWriteOptions::labels, e.g. the primitive of each point in a detected scene: PCL's
// PointXYZL reads it) and a scalar "residual" (e.g. the fitted model's f at each point).
// cloudcompare_fields: the label is written a second time as "scalar_label" and the residual is
// named "scalar_residual": CloudCompare (2.11, also in silent command-line mode) loads vertex
// properties named scalar_* as scalar fields and drops "label" and "residual".
// Binary little endian by default, ASCII on request; double by default (the fit works in double),
// float to halve big files. Written atomically (atomic_file.h): the file is complete or absent.
// Throws InputError "<file>: cannot write: ..." on I/O failure and std::invalid_argument when the
// residuals do not match the points or a value to write is NaN or infinite.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "datasets/clouds/point_cloud.h"

namespace implicitfit {

struct PlyWriteOptions {
  bool ascii = false;       // false: binary_little_endian
  bool single = false;      // float instead of double properties
  std::vector<int> labels;  // empty, or one per point: an int property "label" before "residual"
  std::vector<std::array<std::uint8_t, 3>> colours;  // empty, or one per point: red green blue
  bool cloudcompare_fields = false;  // also "scalar_label"; "scalar_residual" for "residual"
};

void WritePlyFile(const PointCloud& cloud, const std::string& path,
                  const std::vector<double>& residuals = {}, const PlyWriteOptions& options = {});

}  // namespace implicitfit
