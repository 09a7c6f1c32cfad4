#include "datasets/normals/oriented_cloud.h"

#include <stdexcept>

#include "datasets/clouds/cloud_file.h"
#include "datasets/clouds/spatial_order.h"
#include "datasets/normals/normal_estimation.h"

namespace implicitfit {

PointCloud ReadOrientedCloud(const std::string& path, std::string* normals_action,
                             bool estimate_missing, CloudFileInfo* file_info,
                             Neighbourhoods* neighbourhoods, std::vector<size_t>* spatial_order) {
  CloudFileInfo local;
  CloudFileInfo& info = file_info ? *file_info : local;
  PointCloud cloud = ReadCloudFile(path, &info);
  if (spatial_order) {
    spatial_order->clear();
    if (cloud.size() >= kSpatialOrderPoints) {
      *spatial_order = MortonOrder(cloud.points);
      ApplyOrder(*spatial_order, &cloud, &info.labels);
    }
  }
  if (!estimate_missing && !cloud.has_normals()) {
    if (normals_action) *normals_action = "none in the file";
    return cloud;
  }
  NormalOptions options;
  options.viewpoint = info.viewpoint;
  try {
    const NormalResult result = EnsureOrientedNormals(&cloud, options, neighbourhoods);
    if (normals_action) *normals_action = result.action;
  } catch (const std::invalid_argument& e) {
    // Too few points to estimate normals: not an invalid file but degenerate data; the fit
    // that follows fails with its own reason (exit 1).
    if (normals_action) *normals_action = std::string("none (") + e.what() + ")";
  }
  return cloud;
}

}  // namespace implicitfit
