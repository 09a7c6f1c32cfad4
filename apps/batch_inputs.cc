#include "apps/batch_inputs.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <map>

#include "datasets/io_error.h"

namespace implicitfit {
namespace fs = std::filesystem;
namespace {

std::string Trim(const std::string& s) {
  const size_t b = s.find_first_not_of(" \t\r\n");
  if (b == std::string::npos) return "";
  return s.substr(b, s.find_last_not_of(" \t\r\n") - b + 1);
}

void AddDirectory(const std::string& dir, std::vector<std::string>* paths) {
  std::vector<std::string> found;
  std::error_code ec;
  for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec))
    if (IsCloudFileName(it->path().string()) && !it->is_directory()) found.push_back(it->path().string());
  if (ec) throw FileError(dir, "cannot list the directory: " + ec.message());
  std::sort(found.begin(), found.end());
  paths->insert(paths->end(), found.begin(), found.end());
}

void AddManifest(const std::string& manifest, std::vector<std::string>* paths) {
  std::ifstream in(manifest);
  if (!in || fs::is_directory(manifest)) throw FileError(manifest, "cannot read the manifest");
  const fs::path base = fs::path(manifest).parent_path();
  std::string line;
  while (std::getline(in, line)) {
    line = Trim(line);
    if (line.empty() || line[0] == '#') continue;
    const fs::path p(line);
    paths->push_back(p.is_absolute() || base.empty() ? line : (base / p).string());
  }
  if (in.bad()) throw FileError(manifest, "cannot read the manifest");
}

}  // namespace

bool IsCloudFileName(const std::string& path) {
  std::string ext = fs::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext == ".xyz" || ext == ".pwn" || ext == ".txt" || ext == ".ply" || ext == ".pcd";
}

std::vector<BatchInput> ExpandBatchInputs(const std::vector<std::string>& inputs,
                                          const std::vector<std::string>& manifests) {
  std::vector<std::string> paths;
  for (const std::string& input : inputs) {
    if (fs::is_directory(input))
      AddDirectory(input, &paths);
    else
      paths.push_back(input);
  }
  for (const std::string& manifest : manifests) AddManifest(manifest, &paths);

  std::vector<BatchInput> result;
  std::map<std::string, std::string> owner;  // name -> first path
  for (const std::string& path : paths) {
    BatchInput in;
    in.path = path;
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
  const auto bad = [&]() { return InputError("--shard " + text + ": expected i/N with 1 <= i <= N"); };
  if (slash == std::string::npos) throw bad();
  try {
    size_t used_i = 0, used_n = 0;
    const std::string i = text.substr(0, slash), n = text.substr(slash + 1);
    shard.index = std::stoi(i, &used_i);
    shard.count = std::stoi(n, &used_n);
    if (used_i != i.size() || used_n != n.size()) throw bad();
  } catch (const std::logic_error&) {
    throw bad();
  }
  if (shard.count < 1 || shard.index < 1 || shard.index > shard.count) throw bad();
  return shard;
}

std::vector<BatchInput> SelectShard(const std::vector<BatchInput>& all, const Shard& shard) {
  std::vector<BatchInput> mine;
  for (const BatchInput& in : all)
    if (in.index % static_cast<size_t>(shard.count) == static_cast<size_t>(shard.index - 1)) mine.push_back(in);
  return mine;
}

}  // namespace implicitfit
