// Plain-text clouds (.xyz, .pwn, .txt): one point per line, "x y z" or "x y z nx ny nz",
// separated by whitespace and/or commas. Blank lines and lines starting with '#' are skipped.
// Every data line must have the same number of columns (3 or 6). Refused with InputError
// "<file>:<line>: <problem>": other column counts, a token that is not a number, a NaN or
// infinite coordinate, and a file without any point. A NaN, infinite or zero-length normal is
// not an error here: it is left as a zero vector and listed in info->invalid_normals
// (ReadCloudFile re-estimates it from the neighbours).
// Labelled clouds (.xyzl, XyzColumns::kLabelled): "x y z label" on every line, the integer
// label kept in info->labels.
#pragma once

#include <string>

#include "datasets/clouds/cloud_file_info.h"
#include "datasets/clouds/point_cloud.h"

namespace implicitfit {

enum class XyzColumns {
  kPointsOrOriented,  // "x y z" or "x y z nx ny nz" (.xyz .pwn .txt)
  kLabelled,          // "x y z label", label an integer kept in info->labels (.xyzl, e.g. Fit4CAD)
};

PointCloud ReadXyzFile(const std::string& path, CloudFileInfo* info = nullptr,
                       XyzColumns layout = XyzColumns::kPointsOrOriented);
// The same, from text already in memory; `name` is used in messages.
PointCloud ParseXyzText(const std::string& text, const std::string& name,
                        CloudFileInfo* info = nullptr,
                        XyzColumns layout = XyzColumns::kPointsOrOriented);

}  // namespace implicitfit
