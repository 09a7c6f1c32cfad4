// A point cloud's neighbour lists in one flat array: point i's neighbours, nearest first, are
// the first count(i) entries of its row of `stride` slots (stride: the most neighbours a point
// may have). One allocation for the whole cloud instead of one vector per point: at 10^6 points
// and up to 30 neighbours the per-point vectors cost about 170 bytes a point (capacity rounding,
// headers, allocator), the rows 4 bytes a slot plus 2. The search fills the rows in place
// (datasets/normals/neighbourhoods.h), so no second copy is ever made. graph[i] is a read-only
// range (begin/end, size, operator[], empty), so code written for std::vector<std::vector<int>>
// reads it unchanged; the implicit constructor from such lists keeps small hand-made graphs
// (tests) short.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace implicitfit {

class NeighbourGraph {
 public:
  class Row {
   public:
    Row(const int* begin, const int* end) : begin_(begin), end_(end) {}
    const int* begin() const { return begin_; }
    const int* end() const { return end_; }
    size_t size() const { return static_cast<size_t>(end_ - begin_); }
    bool empty() const { return begin_ == end_; }
    int operator[](size_t k) const { return begin_[k]; }

   private:
    const int *begin_, *end_;
  };

  NeighbourGraph() = default;
  // `points` empty rows of `stride` slots (at most 65535).
  NeighbourGraph(size_t points, size_t stride)
      : stride_(stride), slots_(points * stride), counts_(points, 0) {}
  // NOLINTNEXTLINE(google-explicit-constructor): lists read as a graph (tests, small callers)
  NeighbourGraph(const std::vector<std::vector<int>>& lists) {
    for (const auto& l : lists) stride_ = std::max(stride_, l.size());
    slots_.assign(lists.size() * stride_, 0);
    counts_.assign(lists.size(), 0);
    for (size_t i = 0; i < lists.size(); ++i) {
      std::copy(lists[i].begin(), lists[i].end(), slots_.begin() + i * stride_);
      counts_[i] = static_cast<std::uint16_t>(lists[i].size());
    }
  }

  size_t size() const { return counts_.size(); }
  bool empty() const { return counts_.empty(); }
  size_t stride() const { return stride_; }
  Row operator[](size_t i) const {
    const int* b = slots_.data() + i * stride_;
    return Row(b, b + counts_[i]);
  }
  // Filling: the row's slots, then how many of them are neighbours.
  int* Slots(size_t i) { return slots_.data() + i * stride_; }
  void SetCount(size_t i, size_t count) { counts_[i] = static_cast<std::uint16_t>(count); }
  size_t edges() const {
    size_t e = 0;
    for (std::uint16_t c : counts_) e += c;
    return e;
  }

 private:
  size_t stride_ = 0;
  std::vector<int> slots_;
  std::vector<std::uint16_t> counts_;
};

}  // namespace implicitfit
