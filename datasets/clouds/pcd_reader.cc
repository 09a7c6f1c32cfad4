#include "datasets/clouds/pcd_reader.h"

#include <pcl/PCLPointCloud2.h>
#include <pcl/console/print.h>
#include <pcl/io/pcd_io.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <sstream>
#include <vector>

#include "datasets/io/io_error.h"
#include "datasets/clouds/pcl_conversion.h"
#include "datasets/io/input_file.h"
#include "datasets/io/read_limits.h"
#include "datasets/io/token_lines.h"

namespace implicitfit {
namespace {

// Hand-written header check (~100 lines): pcl::PCDReader segfaults on empty and garbage files
// and reads non-numeric ASCII tokens as 0, so the layout must be known before PCL sees the file.
struct PcdHeader {
  std::vector<std::string> fields;
  std::vector<int> sizes, counts;
  std::vector<char> types;
  unsigned long long width = 0, height = 1, points = 0;
  bool has_points = false, has_viewpoint = false;
  Eigen::Vector3d viewpoint = Eigen::Vector3d::Zero();
  std::string data;  // ascii, binary, binary_compressed
  size_t data_offset = 0;
  long data_line = 0;

  unsigned long long point_size() const {
    unsigned long long s = 0;
    for (size_t i = 0; i < sizes.size(); ++i)
      s += static_cast<unsigned long long>(sizes[i]) * counts[i];
    return s;
  }
  size_t values_per_point() const {
    size_t s = 0;
    for (int c : counts) s += c;
    return s;
  }
};

bool ParseCount(const std::string& token, unsigned long long* value) {
  if (token.empty() || token[0] == '-') return false;
  char* end = nullptr;
  errno = 0;
  *value = std::strtoull(token.c_str(), &end, 10);
  return *end == '\0' && errno == 0;
}

PcdHeader ParseHeader(InputFile& file) {
  const std::string& path = file.path();
  if (file.size() == 0) throw FileError(path, "empty file");
  PcdHeader h;
  bool has_width = false;
  std::string text;
  constexpr unsigned long long kMaxHeaderBytes = 16ULL << 20;
  while (true) {
    if (!file.ReadLine(&text, CurrentReadLimits().max_line_bytes))
      throw FileError(path, "header has no DATA line (truncated or not PCD)");
    const long line = file.line_number();
    if (file.offset() > kMaxHeaderBytes)
      throw LineError(path, line, "header longer than 16 MiB (not a PCD header)");
    std::istringstream in(text);
    std::string key;
    in >> key;
    if (key.empty() || key[0] == '#') continue;
    std::vector<std::string> values;
    for (std::string v; in >> v;) values.push_back(v);
    auto bad = [&](const std::string& what) { return LineError(path, line, what); };
    if (key == "VERSION") {
    } else if (key == "FIELDS" || key == "COLUMNS") {
      h.fields = values;
    } else if (key == "SIZE") {
      for (const std::string& v : values) {
        if (v != "1" && v != "2" && v != "4" && v != "8") throw bad("SIZE must be 1, 2, 4 or 8");
        h.sizes.push_back(v[0] - '0');
      }
    } else if (key == "TYPE") {
      for (const std::string& v : values) {
        if (v != "I" && v != "U" && v != "F") throw bad("TYPE must be I, U or F");
        h.types.push_back(v[0]);
      }
    } else if (key == "COUNT") {
      for (const std::string& v : values) {
        unsigned long long c;
        if (!ParseCount(v, &c) || c == 0 || c > 4096)
          throw bad("bad COUNT '" + v.substr(0, 20) + "'");
        h.counts.push_back(static_cast<int>(c));
      }
    } else if (key == "WIDTH") {
      if (values.size() != 1 || !ParseCount(values[0], &h.width)) throw bad("bad WIDTH");
      has_width = true;
    } else if (key == "HEIGHT") {
      if (values.size() != 1 || !ParseCount(values[0], &h.height)) throw bad("bad HEIGHT");
    } else if (key == "POINTS") {
      if (values.size() != 1 || !ParseCount(values[0], &h.points)) throw bad("bad POINTS");
      h.has_points = true;
    } else if (key == "VIEWPOINT") {
      double v[7];
      for (int i = 0; i < 7; ++i) {
        char* e = nullptr;
        if (values.size() != 7 || (v[i] = std::strtod(values[i].c_str(), &e), *e != '\0') ||
            !std::isfinite(v[i]))
          throw bad("VIEWPOINT needs 7 finite numbers");
      }
      h.viewpoint = Eigen::Vector3d(v[0], v[1], v[2]);
      h.has_viewpoint = true;
    } else if (key == "DATA") {
      if (values.size() != 1 ||
          (values[0] != "ascii" && values[0] != "binary" && values[0] != "binary_compressed"))
        throw bad("DATA must be ascii, binary or binary_compressed");
      h.data = values[0];
      break;
    } else {
      throw bad(line == 1 ? "not a PCD file (unknown header line)"
                          : "unknown header keyword '" + key.substr(0, 30) + "'");
    }
  }
  h.data_offset = file.offset();
  h.data_line = file.line_number() + 1;
  if (h.counts.empty()) h.counts.assign(h.fields.size(), 1);
  if (h.fields.empty() || h.sizes.size() != h.fields.size() || h.types.size() != h.fields.size() ||
      h.counts.size() != h.fields.size())
    throw FileError(path, "FIELDS, SIZE, TYPE and COUNT must list the same number of entries");
  if (!has_width) throw FileError(path, "header has no WIDTH");
  if (h.height != 0 && h.width > ~0ULL / h.height)
    throw FileError(path, "WIDTH x HEIGHT overflows");
  if (!h.has_points) h.points = h.width * h.height;
  if (h.points != h.width * h.height)
    throw FileError(path, "POINTS " + std::to_string(h.points) +
                              " is not WIDTH x HEIGHT = " + std::to_string(h.width * h.height));
  if (h.points == 0) throw FileError(path, "no points (POINTS 0)");
  if (h.points > CurrentReadLimits().max_points)
    throw FileError(path, "POINTS " + std::to_string(h.points) + " is more than the limit of " +
                              std::to_string(CurrentReadLimits().max_points) +
                              " points (raise it with --max-points)");
  int xyz = 0;
  for (size_t i = 0; i < h.fields.size(); ++i)
    if (h.fields[i] == "x" || h.fields[i] == "y" || h.fields[i] == "z") {
      if (h.counts[i] != 1 || h.types[i] != 'F' || (h.sizes[i] != 4 && h.sizes[i] != 8))
        throw FileError(path, "field " + h.fields[i] + " must be a single F 4 or F 8 value");
      ++xyz;
    }
  if (xyz != 3) throw FileError(path, "no x, y and z fields (a point cloud needs all three)");
  return h;
}

void CheckAsciiData(const PcdHeader& h, InputFile& file) {
  const std::string& path = file.path();
  const size_t expected = h.values_per_point();
  std::vector<int> coordinate_column;  // value columns that hold x, y, z
  for (size_t i = 0, column = 0; i < h.fields.size(); column += h.counts[i], ++i)
    if (h.fields[i] == "x" || h.fields[i] == "y" || h.fields[i] == "z")
      coordinate_column.push_back(static_cast<int>(column));
  TokenLines lines(&file);
  unsigned long long found = 0;
  while (lines.Next()) {
    const std::vector<std::string>& tokens = lines.tokens();
    const long line = lines.line();
    if (++found > h.points)
      throw LineError(path, line, "more data lines than POINTS " + std::to_string(h.points));
    if (tokens.size() != expected)
      throw LineError(path, line,
                      "expected " + std::to_string(expected) + " values, found " +
                          std::to_string(tokens.size()));
    for (size_t t = 0; t < tokens.size(); ++t) {
      char* e = nullptr;
      const double v = std::strtod(tokens[t].c_str(), &e);
      if (e != tokens[t].c_str() + tokens[t].size())
        throw LineError(path, line, "'" + tokens[t].substr(0, 40) + "' is not a number");
      if (std::isinf(v))
        for (int c : coordinate_column)
          if (static_cast<size_t>(c) == t)
            throw LineError(path, line, "infinite coordinate '" + tokens[t] + "'");
    }
  }
  if (found < h.points)
    throw LineError(path, lines.line() + 1,
                    "data ends after " + std::to_string(found) + " of the " +
                        std::to_string(h.points) + " points the header declares");
}

void CheckBinaryData(const PcdHeader& h, const InputFile& file) {
  const std::string& path = file.path();
  const unsigned long long available =
      file.size() - std::min<unsigned long long>(h.data_offset, file.size());
  const unsigned long long point_size = h.point_size();
  if (h.points > ~0ULL / point_size) throw FileError(path, "POINTS too large");
  const unsigned long long needed = h.points * point_size;
  if (h.data == "binary") {
    if (available < needed)
      throw FileError(path, "truncated: " + std::to_string(h.points) + " points need " +
                                std::to_string(needed) + " bytes, the data has " +
                                std::to_string(available));
    if (available > needed)
      throw FileError(path, std::to_string(available - needed) +
                                " bytes after the declared points (wrong POINTS?)");
    return;
  }
  // binary_compressed: uint32 compressed size, uint32 uncompressed size, then the LZF block.
  std::uint32_t sizes[2];
  if (available < sizeof sizes) throw FileError(path, "truncated: no compressed data block");
  if (!file.ReadAt(h.data_offset, sizes, sizeof sizes))
    throw FileError(path, "truncated: no compressed data block");
  if (sizes[0] > available - sizeof sizes)
    throw FileError(path, "truncated: the compressed block declares " + std::to_string(sizes[0]) +
                              " bytes, the file has " + std::to_string(available - sizeof sizes));
  if (sizes[1] != needed)
    throw FileError(path, "the compressed block holds " + std::to_string(sizes[1]) + " bytes, " +
                              std::to_string(h.points) + " points need " + std::to_string(needed));
  // LZF (PCL's compression) expands at most 88 times: its longest back reference is 3 bytes
  // for 264 output bytes. A block declaring more claims data it cannot hold; PCL would
  // allocate the claimed size first (a 40 MB file declared 7 GB).
  if (static_cast<unsigned long long>(sizes[1]) > 88ULL * sizes[0] + 264)
    throw FileError(path, "the compressed block of " + std::to_string(sizes[0]) +
                              " bytes cannot expand to the " + std::to_string(sizes[1]) +
                              " it declares (corrupt or forged)");
}

}  // namespace

PointCloud ReadPcdFile(const std::string& path, CloudFileInfo* info) {
  PcdHeader header;
  {
    InputFile file(path);  // checked while streaming (read once here, then by PCL)
    header = ParseHeader(file);
    if (header.data == "ascii")
      CheckAsciiData(header, file);
    else
      CheckBinaryData(header, file);
  }

  pcl::console::setVerbosityLevel(pcl::console::L_ALWAYS);
  pcl::PCLPointCloud2 blob;
  Eigen::Vector4f origin;
  Eigen::Quaternionf orientation;
  int version = 0;
  pcl::PCDReader reader;
  if (reader.read(path, blob, origin, orientation, version) < 0)
    throw FileError(path, "malformed PCD data (PCL's reader failed)");

  CloudFileInfo local;
  CloudFileInfo& out = info ? *info : local;
  out = CloudFileInfo();
  out.format = "pcd " + header.data;
  PointCloud cloud = FromPclCloud(blob, path, MissingPointPolicy::kDrop, &out);
  if (out.records != header.points)
    throw FileError(path, "PCL read " + std::to_string(out.records) +
                              " points, the header declares " + std::to_string(header.points));
  if (header.has_viewpoint) out.viewpoint = header.viewpoint;
  return cloud;
}

}  // namespace implicitfit
