// PCD clouds (PCL's format, v0.5-0.7): DATA ascii, binary and binary_compressed; organized
// (HEIGHT > 1) or not; any field types. x y z required; normal_x normal_y normal_z read when
// present; other fields (rgb/rgba, intensity, curvature, ...) ignored and listed in
// CloudFileInfo::ignored_properties.
//
// Parsing is PCL's (pcl::PCDReader). PCL crashes on some malformed files and accepts others
// silently, so the header is checked first (FIELDS/SIZE/TYPE/COUNT agree, WIDTH x HEIGHT =
// POINTS, x y z exist), then the data: ASCII has one line per point with the declared number
// of numeric tokens (errors name the line), binary has exactly POINTS records, a compressed
// block fits in the file and decompresses to POINTS records. Points with a NaN x, y or z are
// "no measurement" (the PCL convention, e.g. organized scans): they are dropped and counted in
// info->dropped_missing. Infinite coordinates are refused. The VIEWPOINT translation, when the
// header has that line, is returned as info->viewpoint. Errors: InputError "<file>[:<line>]: ...".
#pragma once

#include <string>

#include "datasets/clouds/cloud_file_info.h"
#include "datasets/clouds/point_cloud.h"

namespace implicitfit {

PointCloud ReadPcdFile(const std::string& path, CloudFileInfo* info = nullptr);

}  // namespace implicitfit
