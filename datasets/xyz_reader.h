// Plain-text clouds (.xyz, .pwn, .txt): one point per line, "x y z" or "x y z nx ny nz",
// separated by whitespace and/or commas. Blank lines and lines starting with '#' are skipped.
// Every data line must have the same number of columns (3 or 6). Refused with InputError
// "<file>:<line>: <problem>": other column counts, a token that is not a number, NaN or Inf,
// a zero-length normal, and a file without any point.
#pragma once

#include <string>

#include "datasets/point_cloud.h"

namespace implicitfit {

PointCloud ReadXyzFile(const std::string& path);
// The same, from text already in memory; `name` is used in messages.
PointCloud ParseXyzText(const std::string& text, const std::string& name);

}  // namespace implicitfit
