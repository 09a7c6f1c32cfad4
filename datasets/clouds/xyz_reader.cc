#include "datasets/clouds/xyz_reader.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>

#include "datasets/clouds/file_normals.h"
#include "datasets/io/io_error.h"
#include "datasets/io/text_file.h"

namespace implicitfit {
namespace {

bool IsSeparator(char c) { return c == ' ' || c == '\t' || c == ',' || c == '\r'; }

}  // namespace

PointCloud ParseXyzText(const std::string& text, const std::string& name, CloudFileInfo* info,
                        XyzColumns layout) {
  CloudFileInfo local;
  CloudFileInfo& out = info ? *info : local;
  out = CloudFileInfo();
  const bool labelled = layout == XyzColumns::kLabelled;
  out.format = labelled ? "xyzl" : "xyz";
  PointCloud cloud;
  int columns = 0;
  long line_number = 0;
  size_t pos = 0;
  double values[7];
  while (pos < text.size()) {
    size_t end = text.find('\n', pos);
    if (end == std::string::npos) end = text.size();
    ++line_number;
    const char* p = text.data() + pos;
    const char* const line_end = text.data() + end;
    pos = end + 1;
    while (p < line_end && IsSeparator(*p)) ++p;
    if (p == line_end || *p == '#') continue;
    int count = 0;
    while (p < line_end) {
      if (count == 7)
        throw LineError(name, line_number,
                        std::string(labelled ? "expected 4 numbers" : "expected 3 or 6 numbers") +
                            ", found more than 6");
      // strtod needs a terminated token: copy it (tokens are short).
      const char* token_end = p;
      while (token_end < line_end && !IsSeparator(*token_end)) ++token_end;
      const std::string token(p, token_end);
      char* parsed_end = nullptr;
      errno = 0;
      const double v = std::strtod(token.c_str(), &parsed_end);
      if (parsed_end != token.c_str() + token.size() || token.empty())
        throw LineError(name, line_number, "'" + token.substr(0, 40) + "' is not a number");
      if (!std::isfinite(v) && count < 3)
        throw LineError(name, line_number, "NaN or infinite coordinate '" + token + "'");
      values[count++] = v;
      p = token_end;
      while (p < line_end && IsSeparator(*p)) ++p;
    }
    if (labelled && count != 4)
      throw LineError(name, line_number,
                      "expected 4 numbers (x y z label), found " + std::to_string(count));
    if (!labelled && count != 3 && count != 6)
      throw LineError(name, line_number,
                      "expected 3 or 6 numbers (x y z [nx ny nz]), found " + std::to_string(count));
    if (columns == 0) columns = count;
    if (count != columns)
      throw LineError(name, line_number,
                      "found " + std::to_string(count) + " numbers where earlier lines have " +
                          std::to_string(columns));
    cloud.points.emplace_back(values[0], values[1], values[2]);
    if (labelled) {
      if (values[3] != std::floor(values[3]) || std::abs(values[3]) > 1e9)
        throw LineError(name, line_number, "the label must be an integer");
      out.labels.push_back(static_cast<int>(values[3]));
    } else if (count == 6) {
      AddFileNormal(Eigen::Vector3d(values[3], values[4], values[5]), &cloud, &out);
    }
  }
  if (cloud.points.empty()) throw FileError(name, "no points (empty file or only comments)");
  out.records = cloud.size();
  out.normals_in_file = cloud.has_normals();
  return cloud;
}

PointCloud ReadXyzFile(const std::string& path, CloudFileInfo* info, XyzColumns layout) {
  return ParseXyzText(ReadTextFile(path), path, info, layout);
}

}  // namespace implicitfit
