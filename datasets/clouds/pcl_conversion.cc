#include "datasets/clouds/pcl_conversion.h"

#include <pcl/PCLPointCloud2.h>

#include <cmath>
#include <cstdint>
#include <cstring>

#include "datasets/clouds/file_normals.h"
#include "datasets/io/io_error.h"

namespace implicitfit {
namespace {

template <typename T>
double Load(const std::uint8_t* p) {
  T v;
  std::memcpy(&v, p, sizeof v);
  return static_cast<double>(v);
}

// One numeric value of any PCL field type (the PCD and PLY readers keep the file's types).
double FieldValue(const std::uint8_t* p, std::uint8_t datatype) {
  switch (datatype) {
    case pcl::PCLPointField::INT8:
      return Load<std::int8_t>(p);
    case pcl::PCLPointField::UINT8:
      return Load<std::uint8_t>(p);
    case pcl::PCLPointField::INT16:
      return Load<std::int16_t>(p);
    case pcl::PCLPointField::UINT16:
      return Load<std::uint16_t>(p);
    case pcl::PCLPointField::INT32:
      return Load<std::int32_t>(p);
    case pcl::PCLPointField::UINT32:
      return Load<std::uint32_t>(p);
    case pcl::PCLPointField::FLOAT32:
      return Load<float>(p);
    case pcl::PCLPointField::FLOAT64:
      return Load<double>(p);
    default:
      return std::nan("");
  }
}

std::size_t FieldSize(std::uint8_t datatype) {
  switch (datatype) {
    case pcl::PCLPointField::INT8:
    case pcl::PCLPointField::UINT8:
      return 1;
    case pcl::PCLPointField::INT16:
    case pcl::PCLPointField::UINT16:
      return 2;
    case pcl::PCLPointField::INT32:
    case pcl::PCLPointField::UINT32:
    case pcl::PCLPointField::FLOAT32:
      return 4;
    case pcl::PCLPointField::FLOAT64:
      return 8;
    default:
      return 0;
  }
}

const pcl::PCLPointField* FindField(const pcl::PCLPointCloud2& blob, const std::string& name) {
  for (const pcl::PCLPointField& f : blob.fields)
    if (f.name == name) return &f;
  return nullptr;
}

}  // namespace

PointCloud FromPclCloud(const pcl::PCLPointCloud2& blob, const std::string& path,
                        MissingPointPolicy missing, CloudFileInfo* info) {
  const std::size_t records = static_cast<std::size_t>(blob.width) * blob.height;
  const pcl::PCLPointField* xyz[3] = {FindField(blob, "x"), FindField(blob, "y"),
                                      FindField(blob, "z")};
  const pcl::PCLPointField* nxyz[3] = {FindField(blob, "normal_x"), FindField(blob, "normal_y"),
                                       FindField(blob, "normal_z")};
  for (const pcl::PCLPointField* f : xyz)
    if (!f) throw FileError(path, "no x, y and z fields (a point cloud needs all three)");
  const bool has_normals = nxyz[0] && nxyz[1] && nxyz[2];
  // Kept beside the points for viewers (view/): a segmentation's labels and residuals.
  const pcl::PCLPointField* label = FindField(blob, "label");
  const pcl::PCLPointField* residual = FindField(blob, "residual");
  // The readers have already checked the sizes against the header; this guards the offsets.
  for (const pcl::PCLPointField& f : blob.fields) {
    if (FieldSize(f.datatype) == 0)
      throw FileError(path, "field '" + f.name + "' has an unknown type");
    if (f.offset + FieldSize(f.datatype) * std::max<std::uint32_t>(f.count, 1) > blob.point_step)
      throw FileError(path, "field '" + f.name + "' lies outside its point record");
  }
  if (blob.data.size() < records * blob.point_step)
    throw FileError(path, "data shorter than the declared " + std::to_string(records) + " points");

  CloudFileInfo local;
  CloudFileInfo& out = info ? *info : local;
  out.records = records;
  out.normals_in_file = has_normals;
  if (blob.height > 1) {
    out.grid_width = blob.width;
    out.grid_height = blob.height;
  }
  for (const pcl::PCLPointField& f : blob.fields) {
    const bool used =
        f.name == "x" || f.name == "y" || f.name == "z" ||
        (has_normals && (f.name == "normal_x" || f.name == "normal_y" || f.name == "normal_z"));
    if (!used) out.ignored_properties.push_back(f.name);
  }

  PointCloud cloud;
  cloud.points.reserve(records);
  if (has_normals) cloud.normals.reserve(records);
  for (std::size_t i = 0; i < records; ++i) {
    const std::uint8_t* record = blob.data.data() + i * blob.point_step;
    Eigen::Vector3d p;
    for (int k = 0; k < 3; ++k) p[k] = FieldValue(record + xyz[k]->offset, xyz[k]->datatype);
    if (!p.allFinite()) {
      if (missing == MissingPointPolicy::kRefuse || p.array().isInf().any())
        throw FileError(path, "point " + std::to_string(i) + " has a NaN or infinite coordinate");
      ++out.dropped_missing;
      continue;
    }
    cloud.points.push_back(p);
    if (label) {
      const double l = FieldValue(record + label->offset, label->datatype);
      out.labels.push_back(std::isfinite(l) && std::abs(l) < 2e9 ? static_cast<int>(l) : -1);
    }
    if (residual) out.residuals.push_back(FieldValue(record + residual->offset, residual->datatype));
    if (has_normals) {
      Eigen::Vector3d n;
      for (int k = 0; k < 3; ++k) n[k] = FieldValue(record + nxyz[k]->offset, nxyz[k]->datatype);
      AddFileNormal(n, &cloud, &out);
    }
  }
  if (cloud.points.empty()) throw FileError(path, "no points with finite coordinates");
  return cloud;
}

}  // namespace implicitfit
