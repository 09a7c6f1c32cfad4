#include "datasets/clouds/xyz_writer.h"

#include <cstdio>

#include "datasets/io/atomic_file.h"

namespace implicitfit {

std::string FormatXyz(const PointCloud& cloud) {
  std::string out;
  out.reserve(cloud.size() * (cloud.has_normals() ? 140 : 70));
  char line[200];
  for (size_t i = 0; i < cloud.size(); ++i) {
    const Eigen::Vector3d& p = cloud.points[i];
    int n;
    if (cloud.has_normals()) {
      const Eigen::Vector3d& q = cloud.normals[i];
      n = std::snprintf(line, sizeof line, "%.17g %.17g %.17g %.17g %.17g %.17g\n", p.x(), p.y(),
                        p.z(), q.x(), q.y(), q.z());
    } else {
      n = std::snprintf(line, sizeof line, "%.17g %.17g %.17g\n", p.x(), p.y(), p.z());
    }
    out.append(line, n);
  }
  return out;
}

void WriteXyzFile(const PointCloud& cloud, const std::string& path) {
  WriteFileAtomically(path, FormatXyz(cloud));
}

}  // namespace implicitfit
