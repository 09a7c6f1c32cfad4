#include "datasets/io/truth_labels.h"

#include <algorithm>
#include <map>
#include <sstream>

#include "datasets/io/atomic_file.h"
#include "datasets/io/io_error.h"
#include "datasets/io/text_file.h"

namespace implicitfit {

TruthLabels TruthFromValues(const std::vector<long>& values, long none,
                            const std::string& source) {
  TruthLabels t;
  t.source = source;
  std::map<long, int> dense;
  for (long v : values)
    if (v >= 0 && v != none) dense.emplace(v, 0);
  for (auto& [value, index] : dense) {
    index = static_cast<int>(t.ids.size());
    t.ids.push_back(value);
  }
  t.labels.reserve(values.size());
  for (long v : values) t.labels.push_back(v >= 0 && v != none ? dense[v] : -1);
  return t;
}

std::vector<NodeType> ParseKindList(const std::string& list, const std::string& what) {
  std::vector<NodeType> kinds;
  std::stringstream in(list);
  std::string name;
  while (std::getline(in, name, ',')) {
    name.erase(0, name.find_first_not_of(" \t"));
    name.erase(name.find_last_not_of(" \t\r") + 1);
    NodeType kind;
    if (!NodeTypeFromName(name, &kind) ||
        !(kind == NodeType::kPlane || kind == NodeType::kSphere || kind == NodeType::kCylinder ||
          kind == NodeType::kCone || kind == NodeType::kTorus))
      throw InputError(what + ": '" + name + "' is not one of plane, sphere, cylinder, cone, torus");
    kinds.push_back(kind);
  }
  return kinds;
}

TruthLabels ReadTruthFile(const std::string& path, long expected_count, long none) {
  std::istringstream in(ReadTextFile(path));
  std::vector<long> values;
  std::vector<NodeType> kinds;
  std::string line;
  long number = 0;
  const std::string kinds_tag = "kinds:";
  while (std::getline(in, line)) {
    ++number;
    const size_t first = line.find_first_not_of(" \t\r");
    if (first == std::string::npos) throw LineError(path, number, "empty line (expected a label)");
    if (line[first] == '#') {
      const size_t tag = line.find(kinds_tag, first);
      if (tag != std::string::npos)
        kinds = ParseKindList(line.substr(tag + kinds_tag.size()),
                              path + ":" + std::to_string(number));
      continue;
    }
    std::istringstream fields(line);
    long value = 0;
    std::string rest;
    if (!(fields >> value) || (fields >> rest))
      throw LineError(path, number, "expected one integer label, found '" + line + "'");
    values.push_back(value);
  }
  if (expected_count >= 0 && static_cast<long>(values.size()) != expected_count)
    throw FileError(path, std::to_string(values.size()) + " labels for " +
                              std::to_string(expected_count) + " points");
  TruthLabels t = TruthFromValues(values, none, path);
  if (!kinds.empty() && kinds.size() != t.ids.size())
    throw FileError(path, "the kinds line names " + std::to_string(kinds.size()) +
                              " kinds for " + std::to_string(t.ids.size()) + " labelled primitives");
  t.kinds = std::move(kinds);
  return t;
}

void WriteTruthFile(const std::vector<int>& labels, const std::vector<NodeType>& kinds,
                    const std::string& path) {
  std::string text;
  if (!kinds.empty()) {  // the kinds of the labels present, in increasing order
    std::vector<char> present(kinds.size(), 0);
    for (int l : labels)
      if (l >= 0 && static_cast<size_t>(l) < kinds.size()) present[l] = 1;
    text = "# kinds: ";
    bool first = true;
    for (size_t k = 0; k < kinds.size(); ++k)
      if (present[k]) text += std::string(first ? "" : ",") + NodeTypeName(kinds[k]), first = false;
    text += "\n";
  }
  text.reserve(text.size() + labels.size() * 3);
  for (int l : labels) text += std::to_string(l) + "\n";
  WriteFileAtomically(path, text);
}

}  // namespace implicitfit
