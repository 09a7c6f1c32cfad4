// Internal to datasets/: turns a pcl::PCLPointCloud2 (as PCL's PLY and PCD readers return it)
// into a PointCloud. Fields x y z are required (any numeric type); normal_x normal_y normal_z
// (PCL's names, also for PLY nx ny nz) are read when all three exist; every other field is
// listed in CloudFileInfo::ignored_properties. Only a forward declaration of the PCL type is
// needed here, so this header stays free of PCL includes.
#pragma once

#include <string>

#include "datasets/clouds/cloud_file_info.h"
#include "datasets/clouds/point_cloud.h"

namespace pcl {
struct PCLPointCloud2;
}

namespace implicitfit {

enum class MissingPointPolicy {
  kRefuse,  // a NaN or infinite coordinate is an error (unorganized PLY)
  kDrop,    // a point with a NaN coordinate is "no measurement" and dropped; infinity is an error
};

// Throws InputError "<path>: <problem>". Invalid normals (NaN, infinite, zero-length) are left
// as zero vectors and listed in info->invalid_normals.
PointCloud FromPclCloud(const pcl::PCLPointCloud2& blob, const std::string& path,
                        MissingPointPolicy missing, CloudFileInfo* info);

}  // namespace implicitfit
