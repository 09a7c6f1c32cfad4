#include "datasets/clouds/ply_reader.h"

#include <pcl/PCLPointCloud2.h>
#include <pcl/console/print.h>
#include <pcl/io/ply_io.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <sstream>
#include <vector>

#include "datasets/io/io_error.h"
#include "datasets/clouds/pcl_conversion.h"
#include "datasets/io/input_file.h"
#include "datasets/io/read_limits.h"
#include "datasets/io/token_lines.h"

namespace implicitfit {
namespace {

// The header is parsed here (hand-written, ~80 lines) only to validate the data before PCL
// reads it: pcl::PLYReader neither reports line numbers nor notices extra data, wrong token
// counts in ASCII or non-numeric tokens, so those checks need the element layout.
struct PlyProperty {
  std::string name;
  int size = 0;        // bytes of a scalar (or of a list item)
  int count_size = 0;  // bytes of a list's count; 0 for a scalar
};

struct PlyElement {
  std::string name;
  unsigned long long count = 0;
  std::vector<PlyProperty> properties;
  bool has_lists() const {
    for (const PlyProperty& p : properties)
      if (p.count_size) return true;
    return false;
  }
  unsigned long long record_size() const {
    unsigned long long s = 0;
    for (const PlyProperty& p : properties) s += p.size;
    return s;
  }
};

struct PlyHeader {
  std::string format;  // ascii, binary_little_endian, binary_big_endian
  std::vector<PlyElement> elements;
  size_t data_offset = 0;  // first byte after "end_header\n"
  long data_line = 0;      // 1-based line number of the first data line
};

int TypeSize(const std::string& t) {
  if (t == "char" || t == "uchar" || t == "int8" || t == "uint8") return 1;
  if (t == "short" || t == "ushort" || t == "int16" || t == "uint16") return 2;
  if (t == "int" || t == "uint" || t == "int32" || t == "uint32" || t == "float" || t == "float32")
    return 4;
  if (t == "double" || t == "float64") return 8;
  return 0;
}

PlyHeader ParseHeader(InputFile& file) {
  const std::string& path = file.path();
  if (file.size() == 0) throw FileError(path, "empty file");
  PlyHeader h;
  std::string text;
  // Header lines are short; a header of millions of comment lines is refused at 16 MiB.
  constexpr unsigned long long kMaxHeaderBytes = 16ULL << 20;
  while (true) {
    if (!file.ReadLine(&text, CurrentReadLimits().max_line_bytes))
      throw FileError(path, "header has no 'end_header' line (truncated or not PLY)");
    const long line = file.line_number();
    if (!text.empty() && text.back() == '\r') text.pop_back();
    if (line == 1) {
      if (text != "ply") throw LineError(path, 1, "not a PLY file (the first line is not 'ply')");
      continue;
    }
    if (file.offset() > kMaxHeaderBytes)
      throw LineError(path, line, "header longer than 16 MiB (not a PLY header)");
    std::istringstream in(text);
    std::string keyword;
    in >> keyword;
    if (keyword.empty() || keyword == "comment" || keyword == "obj_info") continue;
    if (keyword == "end_header") break;
    if (keyword == "format") {
      std::string version;
      in >> h.format >> version;
      if (h.format != "ascii" && h.format != "binary_little_endian" &&
          h.format != "binary_big_endian")
        throw LineError(path, line, "unknown PLY format '" + h.format + "'");
    } else if (keyword == "element") {
      PlyElement e;
      std::string count;
      in >> e.name >> count;
      char* parsed_end = nullptr;
      errno = 0;
      e.count = std::strtoull(count.c_str(), &parsed_end, 10);
      if (e.name.empty() || count.empty() || *parsed_end != '\0' || errno != 0 || count[0] == '-' ||
          !std::isdigit(static_cast<unsigned char>(count[0])))
        throw LineError(path, line, "malformed element line '" + text.substr(0, 60) + "'");
      if (h.elements.size() >= 1000) throw LineError(path, line, "more than 1000 elements");
      h.elements.push_back(e);
    } else if (keyword == "property") {
      if (h.elements.empty()) throw LineError(path, line, "property before any element");
      std::string type, name;
      in >> type;
      PlyProperty p;
      if (type == "list") {
        std::string count_type, item_type;
        in >> count_type >> item_type >> name;
        p.count_size = TypeSize(count_type);
        p.size = TypeSize(item_type);
        if (!p.count_size || !p.size) throw LineError(path, line, "unknown list property type");
      } else {
        in >> name;
        p.size = TypeSize(type);
        if (!p.size) throw LineError(path, line, "unknown property type '" + type + "'");
      }
      if (name.empty()) throw LineError(path, line, "property without a name");
      p.name = name;
      std::vector<PlyProperty>& properties = h.elements.back().properties;
      for (const PlyProperty& q : properties)
        if (q.name == name)
          throw LineError(path, line, "property '" + name.substr(0, 40) + "' declared twice");
      if (properties.size() >= 1000) throw LineError(path, line, "more than 1000 properties");
      properties.push_back(p);
    } else {
      throw LineError(path, line, "unexpected header line '" + text.substr(0, 60) + "'");
    }
  }
  if (h.format.empty()) throw FileError(path, "header has no 'format' line");
  h.data_offset = file.offset();
  h.data_line = file.line_number() + 1;
  return h;
}

const PlyElement& VertexElement(const PlyHeader& h, const std::string& path) {
  for (const PlyElement& e : h.elements) {
    if (e.name != "vertex") continue;
    int found = 0;
    for (const PlyProperty& p : e.properties)
      if (!p.count_size && (p.name == "x" || p.name == "y" || p.name == "z")) ++found;
    if (found != 3) throw FileError(path, "the vertex element lacks an x, y or z property");
    // pcl::PLYReader aborts the process (SIGABRT, PCL 1.13) on a list property in the vertex
    // element (e.g. "property list uint int idx"); no point cloud needs one.
    for (const PlyProperty& p : e.properties)
      if (p.count_size)
        throw FileError(path, "the vertex element has a list property '" + p.name.substr(0, 40) +
                                  "' (not supported: vertices take scalar properties only)");
    // pcl::PLYReader packs uchar colours into one rgb(a) field assuming "red green blue
    // [alpha]" in a row; any other layout shifts the following properties (checked with PCL
    // 1.13: a lone red corrupts the normals, blue-green-red corrupts x). Refuse it rather than
    // return wrong numbers.
    std::vector<std::string> colours;
    size_t first = 0;
    for (size_t i = 0; i < e.properties.size(); ++i) {
      const PlyProperty& p = e.properties[i];
      if (p.count_size || p.size != 1) continue;
      if (p.name == "red" || p.name == "green" || p.name == "blue" || p.name == "alpha") {
        if (colours.empty()) first = i;
        colours.push_back(p.name);
      }
    }
    if (!colours.empty()) {
      const std::vector<std::string> rgb = {"red", "green", "blue"},
                                     rgba = {"red", "green", "blue", "alpha"};
      bool in_a_row = colours == rgb || colours == rgba;
      for (size_t k = 0; in_a_row && k < colours.size(); ++k)
        in_a_row = e.properties[first + k].name == colours[k];
      if (!in_a_row)
        throw FileError(path,
                        "uchar colour properties must be 'red green blue [alpha]' in a row "
                        "(PCL's PLY reader misreads other layouts)");
    }
    if (e.count == 0) throw FileError(path, "no points (the header declares 0 vertices)");
    if (e.count > CurrentReadLimits().max_points)
      throw FileError(path, "the header declares " + std::to_string(e.count) +
                                " vertices, more than the limit of " +
                                std::to_string(CurrentReadLimits().max_points) +
                                " points (raise it with --max-points)");
    return e;
  }
  throw FileError(path, "no 'element vertex' in the header");
}

bool IsNumber(const std::string& token, double* value) {
  char* end = nullptr;
  *value = std::strtod(token.c_str(), &end);
  return !token.empty() && end == token.c_str() + token.size();
}

// One line per element record, each with the declared tokens; coordinates finite.
void CheckAsciiData(const PlyHeader& h, InputFile& file) {
  const std::string& path = file.path();
  TokenLines lines(&file);
  for (const PlyElement& e : h.elements) {
    const bool vertex = e.name == "vertex";
    for (unsigned long long r = 0; r < e.count; ++r) {
      if (!lines.Next())
        throw LineError(path, lines.line() + 1,
                        "data ends after " + std::to_string(r) + " of the " +
                            std::to_string(e.count) + " '" + e.name +
                            "' records the header declares");
      const std::vector<std::string>& tokens = lines.tokens();
      size_t t = 0;
      double v;
      for (const PlyProperty& p : e.properties) {
        size_t n = 1;
        if (p.count_size) {
          if (t >= tokens.size() || !IsNumber(tokens[t], &v) || v < 0 || v != std::floor(v))
            throw LineError(path, lines.line(), "bad list length in '" + e.name + "' record");
          n = static_cast<size_t>(v);
          ++t;
        }
        for (size_t k = 0; k < n; ++k, ++t) {
          if (t >= tokens.size())
            throw LineError(path, lines.line(),
                            "too few values for the properties of '" + e.name + "'");
          if (!IsNumber(tokens[t], &v))
            throw LineError(path, lines.line(),
                            "'" + tokens[t].substr(0, 40) + "' is not a number");
          if (vertex && !p.count_size && (p.name == "x" || p.name == "y" || p.name == "z") &&
              !std::isfinite(v))
            throw LineError(path, lines.line(), "NaN or infinite coordinate '" + tokens[t] + "'");
        }
      }
      if (t != tokens.size())
        throw LineError(path, lines.line(),
                        "expected " + std::to_string(t) + " values for '" + e.name + "', found " +
                            std::to_string(tokens.size()));
    }
  }
  if (lines.Next())
    throw LineError(path, lines.line(), "more data than the header declares (wrong vertex count?)");
}

// The data size follows from the header up to the first element with list properties (whose
// size depends on the data): the file must have at least that, and exactly that without lists.
void CheckBinarySize(const PlyHeader& h, const InputFile& file, const PlyElement& vertex) {
  const std::string& path = file.path();
  const unsigned long long available = file.size() - std::min<unsigned long long>(h.data_offset, file.size());
  unsigned long long expected = 0;
  bool exact = true;
  for (const PlyElement& e : h.elements) {
    if (e.has_lists()) {
      exact = false;
      break;
    }
    const unsigned long long size = e.record_size();
    if (size && e.count > (available - std::min(expected, available)) / size) {
      expected = available + 1;  // more than the file holds (and no overflow)
      break;
    }
    expected += e.count * size;
  }
  if (expected > available)
    throw FileError(path, "truncated: the header declares " + std::to_string(vertex.count) +
                              " vertices, the data has only " + std::to_string(available) +
                              " bytes, fewer than they need");
  if (exact && available > expected)
    throw FileError(path, std::to_string(available - expected) +
                              " bytes after the data the header declares (wrong vertex count?)");
}

}  // namespace

PointCloud ReadPlyFile(const std::string& path, CloudFileInfo* info) {
  // Checked while streaming (the file is read once here, then by PCL).
  PlyHeader header;
  {
    InputFile file(path);
    header = ParseHeader(file);
    const PlyElement& vertex = VertexElement(header, path);
    if (header.format == "ascii")
      CheckAsciiData(header, file);
    else
      CheckBinarySize(header, file, vertex);
  }
  const PlyElement& vertex = VertexElement(header, path);

  pcl::console::setVerbosityLevel(pcl::console::L_ALWAYS);
  pcl::PCLPointCloud2 blob;
  Eigen::Vector4f origin = Eigen::Vector4f::Zero();
  Eigen::Quaternionf orientation = Eigen::Quaternionf::Identity();
  int version = 0;
  pcl::PLYReader reader;
  if (reader.read(path, blob, origin, orientation, version) < 0)
    throw FileError(path, "malformed PLY data (PCL's reader failed)");

  bool range_grid = false, camera = false;
  for (const PlyElement& e : header.elements) {
    range_grid = range_grid || e.name == "range_grid";
    camera = camera || e.name == "camera";
  }
  CloudFileInfo local;
  CloudFileInfo& out = info ? *info : local;
  out = CloudFileInfo();
  out.format = "ply " + header.format;
  // A range grid's empty cells come back from PCL as NaN points: not points of the file.
  PointCloud cloud = FromPclCloud(
      blob, path, range_grid ? MissingPointPolicy::kDrop : MissingPointPolicy::kRefuse, &out);
  if (cloud.size() != vertex.count)
    throw FileError(path, "the header declares " + std::to_string(vertex.count) + " vertices, " +
                              std::to_string(cloud.size()) + " have finite coordinates");
  if (camera) out.viewpoint = origin.head<3>().cast<double>();
  return cloud;
}

}  // namespace implicitfit
