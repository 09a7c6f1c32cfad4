// Reads any supported cloud by its extension: .xyz/.pwn/.txt and labelled .xyzl (plain text,
// xyz_reader.h),
// .ply (ply_reader.h) and .pcd (pcd_reader.h), the last two only when built with PCL. Other
// extensions are refused with InputError naming the file and the supported list.
// The returned normals are empty or one unit vector per point: normals that were NaN, infinite
// or zero-length in the file are re-estimated from their neighbours (listed in
// info->invalid_normals); if every normal was invalid the cloud comes back without normals.
// Normals are returned as the file gives them (possibly unoriented): see normal_estimation.h
// to estimate missing ones and orient them. `info`, when given, tells what the file held.
#pragma once

#include <functional>
#include <string>

#include "datasets/clouds/cloud_file_info.h"
#include "datasets/clouds/point_cloud.h"

namespace implicitfit {

PointCloud ReadCloudFile(const std::string& path, CloudFileInfo* info = nullptr);

// Whether ReadCloudFile reads `path` by its extension (case-insensitive): the one list, which
// `batch` also uses to pick the clouds of a folder.
bool IsCloudFileName(const std::string& path);
// The extensions it reads, e.g. ".xyz .pwn .txt .xyzl .ply .pcd".
std::string CloudFileExtensions();

// Called after every successful ReadCloudFile (from the reading thread), e.g. for the command
// line to tell the user how many records were dropped (info.dropped_missing: NaN coordinates,
// the "no measurement" of PCD and range grids). Process-wide; empty by default.
using CloudReadObserver = std::function<void(const std::string& path, const CloudFileInfo& info)>;
void SetCloudReadObserver(CloudReadObserver observer);

}  // namespace implicitfit
