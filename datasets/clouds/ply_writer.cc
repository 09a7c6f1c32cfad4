#include "datasets/clouds/ply_writer.h"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <functional>
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
void AppendLittleEndian(std::string* out, T v, bool swap) {
  char bytes[sizeof(T)];
  std::memcpy(bytes, &v, sizeof v);
  if (swap)
    for (size_t i = 0; i < sizeof(T) / 2; ++i) std::swap(bytes[i], bytes[sizeof(T) - 1 - i]);
  out->append(bytes, sizeof v);
}

// One vertex property: its PLY type and the value of point i.
struct Column {
  enum Type { kReal, kInt, kUchar } type;
  std::string name;
  std::function<double(size_t)> value;
};

void CheckSizes(const PointCloud& cloud, const std::vector<double>& residuals,
                const PlyWriteOptions& options) {
  auto check = [&](size_t n, const char* what) {
    if (n != 0 && n != cloud.size())
      throw std::invalid_argument("WritePlyFile: " + std::to_string(n) + " " + what + " for " +
                                  std::to_string(cloud.size()) + " points");
  };
  check(residuals.size(), "residuals");
  check(options.labels.size(), "labels");
  check(options.colours.size(), "colours");
  if (cloud.has_normals() && cloud.normals.size() != cloud.size())
    throw std::invalid_argument("WritePlyFile: normals do not match the points");
}

}  // namespace

// Written by hand rather than through pcl::PLYWriter: that needs a PCLPointCloud2 copy and
// writes to the final path directly, while the output must be composed in memory and renamed
// into place (no partial file); the format itself is a dozen header lines and packed records.
void WritePlyFile(const PointCloud& cloud, const std::string& path,
                  const std::vector<double>& residuals, const PlyWriteOptions& options) {
  CheckSizes(cloud, residuals, options);
  std::vector<Column> columns;
  for (int k = 0; k < 3; ++k)
    columns.push_back(
        {Column::kReal, std::string(1, "xyz"[k]), [&, k](size_t i) { return cloud.points[i][k]; }});
  if (cloud.has_normals())
    for (int k = 0; k < 3; ++k)
      columns.push_back({Column::kReal, std::string("n") + "xyz"[k],
                         [&, k](size_t i) { return cloud.normals[i][k]; }});
  if (!options.colours.empty()) {
    const char* names[3] = {"red", "green", "blue"};
    for (int k = 0; k < 3; ++k)
      columns.push_back(
          {Column::kUchar, names[k], [&, k](size_t i) { return options.colours[i][k]; }});
  }
  if (!options.labels.empty()) {
    columns.push_back({Column::kInt, "label", [&](size_t i) { return options.labels[i]; }});
    if (options.cloudcompare_fields)
      columns.push_back(
          {Column::kInt, "scalar_label", [&](size_t i) { return options.labels[i]; }});
  }
  if (!residuals.empty())
    columns.push_back({Column::kReal, options.cloudcompare_fields ? "scalar_residual" : "residual",
                       [&](size_t i) { return residuals[i]; }});

  const char* real = options.single ? "float" : "double";
  std::string out = "ply\nformat ";
  out += options.ascii ? "ascii" : "binary_little_endian";
  out +=
      " 1.0\ncomment written by implicitfit\nelement vertex " + std::to_string(cloud.size()) + "\n";
  size_t record = 0;
  for (const Column& c : columns) {
    const char* type = c.type == Column::kReal ? real : c.type == Column::kInt ? "int" : "uchar";
    out += std::string("property ") + type + " " + c.name + "\n";
    record += c.type == Column::kReal ? (options.single ? 4 : 8) : c.type == Column::kInt ? 4 : 1;
  }
  out += "end_header\n";

  const bool swap = !HostIsLittleEndian();
  out.reserve(out.size() + cloud.size() * (options.ascii ? 25 * columns.size() : record));
  char text[32];
  for (size_t i = 0; i < cloud.size(); ++i)
    for (size_t k = 0; k < columns.size(); ++k) {
      const Column& c = columns[k];
      const double v = c.value(i);
      if (!std::isfinite(v))
        throw std::invalid_argument("WritePlyFile: " + c.name + " of point " + std::to_string(i) +
                                    " is NaN or infinite");
      if (options.ascii) {
        if (c.type == Column::kReal)
          std::snprintf(text, sizeof text, options.single ? "%.9g" : "%.17g", v);
        else
          std::snprintf(text, sizeof text, "%d", static_cast<int>(v));
        out += text;
        out += k + 1 == columns.size() ? '\n' : ' ';
      } else if (c.type == Column::kInt) {
        AppendLittleEndian<std::int32_t>(&out, static_cast<std::int32_t>(v), swap);
      } else if (c.type == Column::kUchar) {
        out += static_cast<char>(static_cast<std::uint8_t>(v));
      } else if (options.single) {
        AppendLittleEndian<float>(&out, static_cast<float>(v), swap);
      } else {
        AppendLittleEndian<double>(&out, v, swap);
      }
    }
  WriteFileAtomically(path, out);
}

}  // namespace implicitfit
