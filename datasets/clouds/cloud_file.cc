#include "datasets/clouds/cloud_file.h"

#include <algorithm>
#include <cctype>
#include <iterator>
#include <string>
#include <stdexcept>

#include "datasets/io/io_error.h"
#include "datasets/normals/normal_estimation.h"
#include "datasets/clouds/xyz_reader.h"
#ifdef IMPLICITFIT_HAVE_PCL
#include "datasets/clouds/pcd_reader.h"
#include "datasets/clouds/ply_reader.h"
#endif

namespace implicitfit {

namespace {

std::string LowerCaseExtension(const std::string& path) {
  const size_t dot = path.find_last_of('.');
  const size_t slash = path.find_last_of('/');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return "";
  std::string ext = path.substr(dot + 1);
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return std::tolower(c); });
  return ext;
}

#ifdef IMPLICITFIT_HAVE_PCL
const char* const kExtensions[] = {"xyz", "pwn", "txt", "xyzl", "ply", "pcd"};
#else
const char* const kExtensions[] = {"xyz", "pwn", "txt", "xyzl"};
#endif

PointCloud ReadByExtension(const std::string& path, CloudFileInfo* info) {
  const std::string ext = LowerCaseExtension(path);
  if (ext == "xyz" || ext == "pwn" || ext == "txt") return ReadXyzFile(path, info);
  if (ext == "xyzl") return ReadXyzFile(path, info, XyzColumns::kLabelled);
#ifdef IMPLICITFIT_HAVE_PCL
  if (ext == "ply") return ReadPlyFile(path, info);
  if (ext == "pcd") return ReadPcdFile(path, info);
  throw FileError(path, "unsupported cloud format '." + ext + "' (supported: " +
                            CloudFileExtensions() + ")");
#else
  throw FileError(path, "unsupported cloud format '." + ext + "' (supported: " +
                            CloudFileExtensions() + "; .ply and .pcd need a build with PCL)");
#endif
}

CloudReadObserver& Observer() {
  static CloudReadObserver observer;
  return observer;
}

PointCloud ReadAndRepair(const std::string& path, CloudFileInfo& out) {
  PointCloud cloud = ReadByExtension(path, &out);
  if (out.invalid_normals.empty()) return cloud;
  if (out.invalid_normals.size() == cloud.size()) {
    cloud.normals.clear();  // nothing usable: the caller estimates them (normal_estimation.h)
    return cloud;
  }
  try {
    ReestimateNormalsAt(&cloud, out.invalid_normals);
  } catch (const std::invalid_argument&) {
    throw FileError(path,
                    std::to_string(out.invalid_normals.size()) +
                        " normals are NaN, infinite or zero-length and the cloud is too small "
                        "to re-estimate them");
  }
  return cloud;
}

}  // namespace

void SetCloudReadObserver(CloudReadObserver observer) { Observer() = std::move(observer); }

bool IsCloudFileName(const std::string& path) {
  const std::string ext = LowerCaseExtension(path);
  return std::find(std::begin(kExtensions), std::end(kExtensions), ext) != std::end(kExtensions);
}

std::string CloudFileExtensions() {
  std::string list;
  for (const char* ext : kExtensions) list += std::string(list.empty() ? "." : " .") + ext;
  return list;
}

PointCloud ReadCloudFile(const std::string& path, CloudFileInfo* info) {
  CloudFileInfo local;
  CloudFileInfo& out = info ? *info : local;
  PointCloud cloud = ReadAndRepair(path, out);
  if (Observer()) Observer()(path, out);
  return cloud;
}

}  // namespace implicitfit
