#include "model/bernstein/grid_refinement.h"

#include <algorithm>
#include <stdexcept>

namespace implicitfit {
namespace {

long long BaseCubes(const std::array<int, 3>& cells) {
  return 1LL * cells[0] * cells[1] * cells[2];
}

// Appends the subtree of one node from `splits` at position *pos (preorder).
void ParseNode(const std::string& splits, size_t* pos, int level, const std::array<int, 3>& at,
               GridRefinement* r, int index) {
  if (*pos >= splits.size())
    throw std::invalid_argument("the split flags end before every cube is described");
  const char c = splits[(*pos)++];
  if (c != '0' && c != '1')
    throw std::invalid_argument("a split flag must be '0' or '1', found '" + std::string(1, c) +
                                "'");
  if (c == '0') {
    r->node[index] = -1 - static_cast<int>(r->leaves.size());
    r->leaves.push_back({level, at[0], at[1], at[2]});
    r->max_level = std::max(r->max_level, level);
    return;
  }
  if (level + 1 > kMaxRefinementLevel)
    throw std::invalid_argument("the split flags refine beyond level " +
                                std::to_string(kMaxRefinementLevel));
  const int first = static_cast<int>(r->node.size());
  r->node[index] = first;
  r->node.resize(r->node.size() + 8, 0);
  for (int o = 0; o < 8; ++o)
    ParseNode(splits, pos, level + 1,
              {2 * at[0] + (o & 1), 2 * at[1] + ((o >> 1) & 1), 2 * at[2] + ((o >> 2) & 1)}, r,
              first + o);
}

void WriteNode(const GridRefinement& r, int index, std::string* out) {
  if (r.node[index] < 0) {
    out->push_back('0');
    return;
  }
  out->push_back('1');
  for (int o = 0; o < 8; ++o) WriteNode(r, r.node[index] + o, out);
}

// Leaf containing lattice point p given in units of h / 2^units (units >= max_level).
int LeafAtUnits(const std::array<int, 3>& cells, const GridRefinement& r,
                std::array<long long, 3> p, int units) {
  for (int a = 0; a < 3; ++a) p[a] = std::clamp(p[a], 0LL, (1LL * cells[a] << units) - 1);
  const long long c = ((p[2] >> units) * cells[1] + (p[1] >> units)) * cells[0] + (p[0] >> units);
  int node = r.root[c];
  for (int level = 0; r.node[node] >= 0; ++level) {
    const int shift = units - level - 1;
    const int o = static_cast<int>(((p[0] >> shift) & 1) | (((p[1] >> shift) & 1) << 1) |
                                   (((p[2] >> shift) & 1) << 2));
    node = r.node[node] + o;
  }
  return -1 - r.node[node];
}

}  // namespace

GridRefinement UniformRefinement(const std::array<int, 3>& cells) {
  return RefinementFromSplits(cells, std::string(static_cast<size_t>(BaseCubes(cells)), '0'));
}

GridRefinement RefinementFromSplits(const std::array<int, 3>& cells, const std::string& splits) {
  GridRefinement r;
  const long long n = BaseCubes(cells);
  r.node.assign(static_cast<size_t>(n), 0);
  r.root.resize(static_cast<size_t>(n));
  size_t pos = 0;
  for (int l = 0; l < cells[2]; ++l)
    for (int j = 0; j < cells[1]; ++j)
      for (int i = 0; i < cells[0]; ++i) {
        const int c = (l * cells[1] + j) * cells[0] + i;
        r.root[c] = c;
        ParseNode(splits, &pos, 0, {i, j, l}, &r, c);
      }
  if (pos != splits.size())
    throw std::invalid_argument("the split flags go on after every cube is described (" +
                                std::to_string(splits.size() - pos) + " flags too many)");
  return r;
}

std::string SplitsOf(const GridRefinement& r) {
  std::string out;
  for (int root : r.root) WriteNode(r, root, &out);
  return out;
}

GridRefinement SplitLeaves(const std::array<int, 3>& cells, const GridRefinement& r,
                           const std::vector<bool>& split, std::vector<int>* parent_of) {
  std::string out;
  std::vector<int> parents;
  // Preorder rewrite: a split leaf becomes '1' + 8 leaves.
  const auto write = [&](auto&& self, int index) -> void {
    if (r.node[index] < 0) {
      const int leaf = -1 - r.node[index];
      const int copies = split[leaf] ? 8 : 1;
      if (split[leaf]) out.push_back('1');
      for (int o = 0; o < copies; ++o) {
        out.push_back('0');
        parents.push_back(leaf);
      }
      return;
    }
    out.push_back('1');
    for (int o = 0; o < 8; ++o) self(self, r.node[index] + o);
  };
  for (int root : r.root) write(write, root);
  if (parent_of) *parent_of = parents;
  return RefinementFromSplits(cells, out);
}

int LeafAt(const std::array<int, 3>& cells, const GridRefinement& r,
           const std::array<long long, 3>& p, int units) {
  return LeafAtUnits(cells, r, p, units);
}

std::vector<bool> BalanceSplits(const std::array<int, 3>& cells, const GridRefinement& r,
                                std::vector<bool> split) {
  // A leaf at level L that will be split has children at L + 1: every leaf touching it must be
  // at level >= L, else it is split too (and so on). Neighbours are found at the centres of the
  // 26 level-L cubes around it, in units of h / 2^(max_level + 1).
  const int units = r.max_level + 1;
  std::vector<int> work;
  for (size_t q = 0; q < split.size(); ++q)
    if (split[q]) work.push_back(static_cast<int>(q));
  while (!work.empty()) {
    const int q = work.back();
    work.pop_back();
    const auto& leaf = r.leaves[q];
    const int level = leaf[0];
    const long long size = 1LL << (units - level);
    for (int dz = -1; dz <= 1; ++dz)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          if (!dx && !dy && !dz) continue;
          const long long d[3] = {dx, dy, dz};
          std::array<long long, 3> p;
          bool inside = true;
          for (int a = 0; a < 3; ++a) {
            const long long i = leaf[1 + a] + d[a];
            inside = inside && i >= 0 && i < (1LL * cells[a] << level);
            p[a] = i * size + size / 2;
          }
          if (!inside) continue;
          const int other = LeafAtUnits(cells, r, p, units);
          if (r.leaves[other][0] < level && !split[other]) {
            split[other] = true;
            work.push_back(other);
          }
        }
  }
  return split;
}

}  // namespace implicitfit
