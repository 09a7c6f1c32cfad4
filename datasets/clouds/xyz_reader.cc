#include "datasets/clouds/xyz_reader.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>

#include "datasets/clouds/file_normals.h"
#include "datasets/io/input_file.h"
#include "datasets/io/io_error.h"
#include "datasets/io/read_limits.h"

namespace implicitfit {
namespace {

bool IsSeparator(char c) { return c == ' ' || c == '\t' || c == ',' || c == '\r'; }

// One data line at a time, so that a file is parsed as it is read (memory: the points).
class XyzParser {
 public:
  XyzParser(const std::string& name, CloudFileInfo* info, XyzColumns layout)
      : name_(name), out_(*info), labelled_(layout == XyzColumns::kLabelled) {
    out_ = CloudFileInfo();
    out_.format = labelled_ ? "xyzl" : "xyz";
  }

  void Line(const char* p, const char* const line_end, long line_number) {
    while (p < line_end && IsSeparator(*p)) ++p;
    if (p == line_end || *p == '#') return;
    int count = 0;
    double values[7];
    while (p < line_end) {
      if (count == 7)
        throw LineError(name_, line_number,
                        std::string(labelled_ ? "expected 4 numbers" : "expected 3 or 6 numbers") +
                            ", found more than 6");
      // strtod needs a terminated token: copy it (tokens are short).
      const char* token_end = p;
      while (token_end < line_end && !IsSeparator(*token_end)) ++token_end;
      const std::string token(p, token_end);
      char* parsed_end = nullptr;
      errno = 0;
      const double v = std::strtod(token.c_str(), &parsed_end);
      if (parsed_end != token.c_str() + token.size() || token.empty())
        throw LineError(name_, line_number, "'" + token.substr(0, 40) + "' is not a number");
      if (!std::isfinite(v) && count < 3)
        throw LineError(name_, line_number, "NaN or infinite coordinate '" + token + "'");
      values[count++] = v;
      p = token_end;
      while (p < line_end && IsSeparator(*p)) ++p;
    }
    if (labelled_ && count != 4)
      throw LineError(name_, line_number,
                      "expected 4 numbers (x y z label), found " + std::to_string(count));
    if (!labelled_ && count != 3 && count != 6)
      throw LineError(name_, line_number,
                      "expected 3 or 6 numbers (x y z [nx ny nz]), found " + std::to_string(count));
    if (columns_ == 0) columns_ = count;
    if (count != columns_)
      throw LineError(name_, line_number,
                      "found " + std::to_string(count) + " numbers where earlier lines have " +
                          std::to_string(columns_));
    if (cloud_.points.size() >= CurrentReadLimits().max_points)
      throw LineError(name_, line_number,
                      "more than " + std::to_string(CurrentReadLimits().max_points) +
                          " points, the limit (raise it with --max-points)");
    cloud_.points.emplace_back(values[0], values[1], values[2]);
    if (labelled_) {
      if (values[3] != std::floor(values[3]) || std::abs(values[3]) > 1e9)
        throw LineError(name_, line_number, "the label must be an integer");
      out_.labels.push_back(static_cast<int>(values[3]));
    } else if (count == 6) {
      AddFileNormal(Eigen::Vector3d(values[3], values[4], values[5]), &cloud_, &out_);
    }
  }

  PointCloud Finish() {
    if (cloud_.points.empty()) throw FileError(name_, "no points (empty file or only comments)");
    out_.records = cloud_.size();
    out_.normals_in_file = cloud_.has_normals();
    return std::move(cloud_);
  }

 private:
  const std::string& name_;
  CloudFileInfo& out_;
  const bool labelled_;
  int columns_ = 0;
  PointCloud cloud_;
};

}  // namespace

PointCloud ParseXyzText(const std::string& text, const std::string& name, CloudFileInfo* info,
                        XyzColumns layout) {
  CloudFileInfo local;
  XyzParser parser(name, info ? info : &local, layout);
  long line_number = 0;
  size_t pos = 0;
  while (pos < text.size()) {
    size_t end = text.find('\n', pos);
    if (end == std::string::npos) end = text.size();
    parser.Line(text.data() + pos, text.data() + end, ++line_number);
    pos = end + 1;
  }
  return parser.Finish();
}

PointCloud ReadXyzFile(const std::string& path, CloudFileInfo* info, XyzColumns layout) {
  CloudFileInfo local;
  XyzParser parser(path, info ? info : &local, layout);
  InputFile file(path);
  std::string line;
  while (file.ReadLine(&line, CurrentReadLimits().max_line_bytes))
    parser.Line(line.data(), line.data() + line.size(), file.line_number());
  return parser.Finish();
}

}  // namespace implicitfit
