// Reads a cloud file and makes sure it has consistently oriented normals: the file's normals
// are kept (re-oriented when their signs are inconsistent), missing ones are estimated and
// oriented toward the file's viewpoint when it gives one, else by MST propagation
// (datasets/normals/normal_estimation.h). `normals_action` says which happened, for reports.
// Throws InputError naming the file when it cannot be read. A cloud too small to estimate
// normals is returned without them (`normals_action` says so): degenerate data, left to the
// fit to refuse with exit 1.
// estimate_missing false: a file without normals is returned without them ("none in the file").
// info (optional) receives what the reader found (CloudFileInfo: labels, viewpoint, ...);
// neighbourhoods (optional) the neighbourhoods the normals were estimated or checked with
// (empty when there were none). spatial_order (optional): clouds of at least
// kSpatialOrderPoints points are put in Morton order (datasets/clouds/spatial_order.h) right
// after reading, before the normals, with info's labels; *spatial_order then holds the order
// (point k of the result is point spatial_order[k] of the file), else it is left empty.
#pragma once

#include <string>

#include "datasets/clouds/cloud_file_info.h"
#include "datasets/clouds/point_cloud.h"
#include "datasets/normals/neighbourhoods.h"

namespace implicitfit {

// Below this many points a cloud's working set fits in the caches and the order brings nothing.
constexpr size_t kSpatialOrderPoints = 100000;

PointCloud ReadOrientedCloud(const std::string& path, std::string* normals_action,
                             bool estimate_missing = true, CloudFileInfo* info = nullptr,
                             Neighbourhoods* neighbourhoods = nullptr,
                             std::vector<size_t>* spatial_order = nullptr);

}  // namespace implicitfit
