// PLY clouds (the "vertex" element): ASCII, binary_little_endian and binary_big_endian; any
// numeric property type; x y z required, nx ny nz (or normal_x normal_y normal_z) read when all
// three exist; every other property (colour, intensity, segment_index, ...) is ignored and
// listed in CloudFileInfo::ignored_properties. Faces and other elements are skipped. A
// range_grid element (Stanford range scans) gives an organized cloud whose empty cells are
// not points.
//
// Parsing is PCL's (pcl::PLYReader). Because PCL accepts some malformed files silently, the
// header and the data are checked first: the header must be complete; ASCII data must have one
// line per element record with the declared number of numeric tokens (errors name the line);
// binary data must have exactly the size the header implies (truncated files and wrong vertex
// counts are refused). NaN or infinite coordinates are refused. Invalid normals (NaN, infinite,
// zero-length) are left as zero vectors and listed in info->invalid_normals (ReadCloudFile
// re-estimates them). Errors: InputError "<file>[:<line>]: <problem>".
#pragma once

#include <string>

#include "datasets/clouds/cloud_file_info.h"
#include "datasets/clouds/point_cloud.h"

namespace implicitfit {

PointCloud ReadPlyFile(const std::string& path, CloudFileInfo* info = nullptr);

}  // namespace implicitfit
