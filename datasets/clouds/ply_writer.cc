#include "datasets/clouds/ply_writer.h"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <stdexcept>

#include "datasets/io/atomic_file.h"

namespace implicitfit {
namespace {

bool HostIsLittleEndian() {
  const std::uint16_t one = 1;
  std::uint8_t first;
  std::memcpy(&first, &one, 1);
  return first == 1;
}

template <typename T>
void AppendLittleEndian(std::string* out, double value, bool swap) {
  const T v = static_cast<T>(value);
  char bytes[sizeof(T)];
  std::memcpy(bytes, &v, sizeof v);
  if (swap)
    for (size_t i = 0; i < sizeof(T) / 2; ++i) std::swap(bytes[i], bytes[sizeof(T) - 1 - i]);
  out->append(bytes, sizeof v);
}

}  // namespace

// Written by hand rather than through pcl::PLYWriter: that needs a PCLPointCloud2 copy and
// writes to the final path directly, while the output must be composed in memory and renamed
// into place (no partial file); the format itself is a dozen header lines and packed records.
void WritePlyFile(const PointCloud& cloud, const std::string& path,
                  const std::vector<double>& residuals, const PlyWriteOptions& options) {
  if (!residuals.empty() && residuals.size() != cloud.size())
    throw std::invalid_argument("WritePlyFile: " + std::to_string(residuals.size()) +
                                " residuals for " + std::to_string(cloud.size()) + " points");
  if (cloud.has_normals() && cloud.normals.size() != cloud.size())
    throw std::invalid_argument("WritePlyFile: normals do not match the points");
  if (!options.labels.empty() && options.labels.size() != cloud.size())
    throw std::invalid_argument("WritePlyFile: " + std::to_string(options.labels.size()) +
                                " labels for " + std::to_string(cloud.size()) + " points");
  const bool has_labels = !options.labels.empty();
  const char* type = options.single ? "float" : "double";
  std::string out = "ply\nformat ";
  out += options.ascii ? "ascii" : "binary_little_endian";
  out +=
      " 1.0\ncomment written by implicitfit\nelement vertex " + std::to_string(cloud.size()) + "\n";
  std::vector<std::string> names = {"x", "y", "z"};
  if (cloud.has_normals()) names.insert(names.end(), {"nx", "ny", "nz"});
  for (const std::string& name : names) out += std::string("property ") + type + " " + name + "\n";
  if (has_labels) out += "property int label\n";
  if (!residuals.empty()) {
    names.push_back("residual");
    out += std::string("property ") + type + " residual\n";
  }
  out += "end_header\n";

  const bool swap = !HostIsLittleEndian();
  const size_t width = names.size();
  out.reserve(out.size() + cloud.size() * width * (options.ascii ? 25 : options.single ? 4 : 8));
  double row[7];
  char text[32];
  for (size_t i = 0; i < cloud.size(); ++i) {
    for (int k = 0; k < 3; ++k) row[k] = cloud.points[i][k];
    if (cloud.has_normals())
      for (int k = 0; k < 3; ++k) row[3 + k] = cloud.normals[i][k];
    if (!residuals.empty()) row[width - 1] = residuals[i];
    const size_t label_at = cloud.has_normals() ? 6 : 3;  // the label precedes the residual
    auto append_label = [&]() {
      if (options.ascii) {
        out += std::to_string(options.labels[i]);
        out += label_at == width ? '\n' : ' ';
      } else {
        const std::int32_t v = options.labels[i];
        char bytes[4];
        std::memcpy(bytes, &v, 4);
        if (swap) std::swap(bytes[0], bytes[3]), std::swap(bytes[1], bytes[2]);
        out.append(bytes, 4);
      }
    };
    for (size_t k = 0; k < width; ++k) {
      if (has_labels && k == label_at) append_label();
      if (!std::isfinite(row[k]))
        throw std::invalid_argument("WritePlyFile: " + names[k] + " of point " + std::to_string(i) +
                                    " is NaN or infinite");
      if (options.ascii) {
        std::snprintf(text, sizeof text, options.single ? "%.9g" : "%.17g", row[k]);
        out += text;
        out += k + 1 == width && !(has_labels && label_at == width) ? '\n' : ' ';
      } else if (options.single) {
        AppendLittleEndian<float>(&out, row[k], swap);
      } else {
        AppendLittleEndian<double>(&out, row[k], swap);
      }
    }
    if (has_labels && label_at == width) append_label();
  }
  WriteFileAtomically(path, out);
}

}  // namespace implicitfit
