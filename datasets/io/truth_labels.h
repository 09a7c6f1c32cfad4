// Ground-truth segmentations for scoring a detection (`detect --score`, `detect --truth`,
// `sample --truth`). A truth file is one integer label per line, in the cloud's point order
// (the format of `detect --labels`), a negative value meaning "on no primitive" (outliers,
// clutter); `#` lines are comments, and a comment
//   # kinds: plane,sphere,cylinder
// gives the kind of each truth primitive: the k-th kind belongs to the k-th smallest label
// value (`sample --truth` writes labels 0..G-1 and this line). Labels may also come from the
// cloud itself (the .xyzl label column, a PLY or PCD integer property "label", "scalar_label"
// or "segment_index": CloudFileInfo::labels). Any label values are accepted: they are mapped
// to 0..G-1 in increasing order (Fit4CAD numbers its primitives from 1); `none` names one more
// value that means "on no primitive" (some data sets use 0 for unlabelled points).
#pragma once

#include <string>
#include <vector>

#include "model/model.h"

namespace implicitfit {

struct TruthLabels {
  std::vector<int> labels;      // per point: 0..G-1, -1 on no primitive
  std::vector<long> ids;        // the label value of each truth primitive (G of them)
  std::vector<NodeType> kinds;  // G kinds, or empty when not known
  std::string source;           // where the labels came from, for messages
};

// Dense labels from raw values (negative or equal to `none`: -1).
TruthLabels TruthFromValues(const std::vector<long>& values, long none, const std::string& source);

// Reads a truth file; InputError "<file>:<line>: ..." for a bad line, a count that is not
// `expected_count` (when >= 0) or a kinds line whose length is not the number of primitives.
TruthLabels ReadTruthFile(const std::string& path, long expected_count = -1, long none = -1);

// "plane,sphere" -> kinds, in order (repeats kept); InputError naming `what` for an unknown
// name.
std::vector<NodeType> ParseKindList(const std::string& list, const std::string& what);

// Writes labels (-1 .. G-1) with the kinds line (when kinds is not empty: the kinds of the
// labels present), atomically.
void WriteTruthFile(const std::vector<int>& labels, const std::vector<NodeType>& kinds,
                    const std::string& path);

}  // namespace implicitfit
