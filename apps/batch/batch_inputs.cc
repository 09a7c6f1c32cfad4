#include "apps/batch/batch_inputs.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <sstream>
#include <map>

#include "apps/option_validators.h"
#include "datasets/clouds/cloud_file.h"
#include "datasets/io/io_error.h"
#include "datasets/io/text_file.h"
#include "fit/primitive/primitive_fitter.h"

namespace implicitfit {
namespace fs = std::filesystem;
namespace {

std::string Trim(const std::string& s) {
  const size_t b = s.find_first_not_of(" \t\r\n");
  if (b == std::string::npos) return "";
  return s.substr(b, s.find_last_not_of(" \t\r\n") - b + 1);
}

struct Entry {
  std::string path, kind;  // kind: from a manifest line, or empty
};

void AddDirectory(const std::string& dir, std::vector<Entry>* entries) {
  std::vector<std::string> found;
  std::error_code ec;
  for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec))
    if (IsCloudFileName(it->path().string()) && !it->is_directory())
      found.push_back(it->path().string());
  if (ec) throw FileError(dir, "cannot list the directory: " + ec.message());
  std::sort(found.begin(), found.end());
  for (const std::string& path : found) entries->push_back({path, ""});
}

void AddManifest(const std::string& manifest, std::vector<Entry>* entries) {
  std::istringstream in(ReadTextFile(manifest));  // a regular file (never a FIFO), size-capped
  const fs::path base = fs::path(manifest).parent_path();
  std::string line;
  for (long number = 1; std::getline(in, line); ++number) {
    line = Trim(line);
    if (line.empty() || line[0] == '#') continue;
    Entry e;
    const size_t tab = line.find('\t');
    if (tab != std::string::npos) {
      e.kind = Trim(line.substr(tab + 1));
      line = Trim(line.substr(0, tab));
      NodeType type;
      if (!FittableKindFromName(e.kind, &type))
        throw LineError(manifest, number,
                        "unknown kind '" + e.kind + "' (" + FittableKindNames() + ")");
    }
    const fs::path p(line);
    e.path = p.is_absolute() || base.empty() ? line : (base / p).string();
    entries->push_back(e);
  }
}

}  // namespace

std::vector<BatchInput> ExpandBatchInputs(const std::vector<std::string>& inputs,
                                          const std::vector<std::string>& manifests) {
  std::vector<Entry> entries;
  for (const std::string& input : inputs) {
    if (fs::is_directory(input))
      AddDirectory(input, &entries);
    else
      entries.push_back({input, ""});
  }
  for (const std::string& manifest : manifests) AddManifest(manifest, &entries);

  std::vector<BatchInput> result;
  std::map<std::string, std::string> owner;  // name -> first path
  for (const auto& [path, kind] : entries) {
    BatchInput in;
    in.path = path;
    in.kind = kind;
    in.name = fs::path(path).stem().string();
    in.index = result.size();
    if (in.name.empty() || in.name == "." || in.name == "..")
      throw FileError(path, "cannot derive an output name from this path");
    auto [it, inserted] = owner.emplace(in.name, path);
    if (!inserted)
      throw InputError("inputs " + it->second + " and " + path + " would both write " + in.name +
                       ".model.json: rename one or run them in separate --out-dir");
    result.push_back(in);
  }
  return result;
}

Shard ParseShard(const std::string& text) {
  Shard shard;
  const size_t slash = text.find('/');
  const auto bad = [&]() {
    return InputError("--shard " + text + ": expected i/N with 1 <= i <= N");
  };
  if (slash == std::string::npos) throw bad();
  try {
    shard.count = static_cast<int>(ParseDecimalInteger(text.substr(slash + 1), "--shard", 1, 1000000));
    shard.index = static_cast<int>(ParseDecimalInteger(text.substr(0, slash), "--shard", 1, shard.count));
  } catch (const InputError&) {
    throw bad();
  }
  if (shard.count < 1 || shard.index < 1 || shard.index > shard.count) throw bad();
  return shard;
}

std::vector<BatchInput> SelectShard(const std::vector<BatchInput>& all, const Shard& shard) {
  std::vector<BatchInput> mine;
  for (const BatchInput& in : all)
    if (in.index % static_cast<size_t>(shard.count) == static_cast<size_t>(shard.index - 1))
      mine.push_back(in);
  return mine;
}

}  // namespace implicitfit
