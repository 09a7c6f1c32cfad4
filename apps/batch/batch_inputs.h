// The input list of `implicitfit batch`: what each command-line INPUT stands for, the output
// name of each cloud, and the --shard selection.
//   - a directory: every supported cloud directly inside it (.xyz .pwn .txt .ply .pcd, by
//     extension, case-insensitive), sorted by name; not recursive;
//   - --manifest FILE: one cloud per line, "PATH" or "PATH<TAB>KIND" (KIND, e.g. cylinder,
//     replaces --model for that cloud; a tab so that paths may hold spaces); blank lines and
//     lines starting with '#' are ignored, surrounding whitespace is trimmed, relative paths are
//     relative to the manifest's folder (a manifest is never guessed from a .txt name: .txt is
//     a cloud format);
//   - anything else: one cloud file (it may fail on its own later, e.g. missing or unreadable).
// Inputs keep the command-line order (positional INPUTS first, then the manifests), each
// directory expanded in place. The output name of a cloud is its file name without the last
// extension ("scans/part_01.ply" -> "part_01"); two inputs with one name are an InputError.
// --shard i/N (1-based, 1 <= i <= N) keeps the inputs whose 0-based index k in that list has
// k mod N == i - 1: shards 1/N .. N/N are disjoint and cover every input.
#pragma once

#include <string>
#include <vector>

namespace implicitfit {

struct BatchInput {
  std::string path;  // the cloud file
  std::string name;  // output base name: DIR/<name>.model.json, DIR/<name>.report.json
  size_t index = 0;  // position in the full (unsharded) list
  std::string kind;  // from a manifest line; empty: --model
};

// Throws InputError for an unreadable directory or manifest, an unknown KIND in a manifest
// (naming the file and line), or duplicate output names.
std::vector<BatchInput> ExpandBatchInputs(const std::vector<std::string>& inputs,
                                          const std::vector<std::string>& manifests);

struct Shard {
  int index = 1;  // 1-based
  int count = 1;
};

// "2/8" -> {2, 8}; InputError unless 1 <= i <= N.
Shard ParseShard(const std::string& text);

// The inputs of one shard, in order.
std::vector<BatchInput> SelectShard(const std::vector<BatchInput>& all, const Shard& shard);

}  // namespace implicitfit
