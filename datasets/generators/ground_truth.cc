#include "datasets/generators/ground_truth.h"

#include <fstream>
#include <sstream>

#include "datasets/io/io_error.h"

namespace implicitfit {

std::vector<NodeType> ReadFit4CadKinds(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw FileError(path, "cannot open");
  std::vector<NodeType> kinds;
  std::string line;
  int number = 0;
  while (std::getline(in, line)) {
    ++number;
    const size_t open = line.find(":=[");
    if (open == std::string::npos) continue;
    const size_t comma = line.find(',', open);
    if (comma == std::string::npos) throw LineError(path, number, "expected \"Kind, [...]\"");
    std::string name = line.substr(open + 3, comma - open - 3);
    for (char& c : name) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    NodeType kind;
    if (!NodeTypeFromName(name, &kind) || IsOperator(kind))
      throw LineError(path, number, "unknown primitive kind '" + name + "'");
    kinds.push_back(kind);
  }
  if (kinds.empty()) throw FileError(path, "no primitive");
  return kinds;
}

std::vector<std::vector<double>> ReadFit4CadCoefficients(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw FileError(path, "cannot open");
  std::vector<std::vector<double>> all;
  std::string line;
  int number = 0;
  while (std::getline(in, line)) {
    ++number;
    const size_t open = line.find(":=[");
    if (open == std::string::npos) continue;
    const size_t a = line.find('[', open + 3), b = line.find(']', a == std::string::npos ? 0 : a);
    if (a == std::string::npos || b == std::string::npos)
      throw LineError(path, number, "expected [coefficients]");
    std::istringstream words(line.substr(a + 1, b - a - 1));
    std::vector<double> c;
    double v;
    while (words >> v) c.push_back(v);
    if (c.empty()) throw LineError(path, number, "no coefficients");
    all.push_back(std::move(c));
  }
  return all;
}

std::vector<int> ReadPlyIntProperty(const std::string& path, const std::string& property) {
  std::ifstream in(path);
  if (!in) throw FileError(path, "cannot open");
  std::string line;
  int number = 0, column = -1, columns = 0;
  long count = -1;
  bool in_vertex = false;
  while (std::getline(in, line)) {
    ++number;
    std::istringstream words(line);
    std::string w;
    words >> w;
    if (w == "format") {
      std::string f;
      words >> f;
      if (f != "ascii") throw LineError(path, number, "only ASCII PLY is read for labels");
    } else if (w == "element") {
      std::string name;
      words >> name;
      in_vertex = name == "vertex";
      if (in_vertex) words >> count;
    } else if (w == "property" && in_vertex) {
      std::string type, name;
      words >> type >> name;
      if (name == property) column = columns;
      ++columns;
    } else if (w == "end_header") {
      break;
    }
  }
  if (column < 0) throw FileError(path, "no vertex property '" + property + "'");
  std::vector<int> values;
  values.reserve(count > 0 ? count : 0);
  while (static_cast<long>(values.size()) < count && std::getline(in, line)) {
    ++number;
    std::istringstream words(line);
    double v = 0;
    for (int k = 0; k <= column; ++k)
      if (!(words >> v)) throw LineError(path, number, "too few values");
    values.push_back(static_cast<int>(v));
  }
  if (static_cast<long>(values.size()) != count)
    throw FileError(path, "fewer vertices than the header says");
  return values;
}

}  // namespace implicitfit
