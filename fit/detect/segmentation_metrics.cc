#include "fit/detect/segmentation_metrics.h"

#include <cmath>
#include <map>
#include <stdexcept>
#include <string>

namespace implicitfit {

namespace {

// truth_kinds null: kinds not known (every kind agrees).
SegmentationMetrics Compare(const std::vector<int>& truth, int G,
                            const std::vector<NodeType>* truth_kinds,
                            const std::vector<int>& detected,
                            const std::vector<NodeType>& detected_kinds, double min_fraction) {
  auto same_kind_as = [&](int g, NodeType kind) {
    return !truth_kinds || (*truth_kinds)[g] == kind;
  };
  if (truth.size() != detected.size())
    throw std::invalid_argument("CompareSegmentations: " + std::to_string(truth.size()) +
                                " truth labels, " + std::to_string(detected.size()) +
                                " detected labels");
  const int D = static_cast<int>(detected_kinds.size());
  std::vector<long> g_size(G, 0), d_size(D, 0);
  std::map<std::pair<int, int>, long> overlap;
  long labelled = 0, covered = 0;
  for (size_t i = 0; i < truth.size(); ++i) {
    const int g = truth[i], d = detected[i];
    if (g < -1 || g >= G || d < -1 || d >= D)
      throw std::invalid_argument("CompareSegmentations: label out of range");
    if (g >= 0) ++g_size[g], ++labelled;
    if (d >= 0) ++d_size[d];
    if (g >= 0 && d >= 0) ++overlap[{g, d}], ++covered;
  }
  const double N = static_cast<double>(truth.size());
  // Most-overlapping partner of each side (smallest index on ties).
  std::vector<int> g_match(G, -1), d_match(D, -1);
  std::vector<long> g_best(G, 0), d_best(D, 0);
  for (const auto& [gd, n] : overlap) {
    if (n > g_best[gd.first]) g_best[gd.first] = n, g_match[gd.first] = gd.second;
    if (n > d_best[gd.second]) d_best[gd.second] = n, d_match[gd.second] = gd.first;
  }
  auto iou = [&](int g, int d) {
    const auto it = overlap.find({g, d});
    const double n = it == overlap.end() ? 0.0 : static_cast<double>(it->second);
    return n / static_cast<double>(g_size[g] + d_size[d] - n);
  };
  SegmentationMetrics m;
  m.match = g_match;
  m.iou.assign(G, 0.0);
  int same_kind = 0;
  for (int g = 0; g < G; ++g) {
    if (g_match[g] >= 0) m.iou[g] = iou(g, g_match[g]);
    if (g_size[g] < min_fraction * N) continue;
    ++m.truth_counted;
    m.mean_iou += m.iou[g];
    if (m.iou[g] >= 0.5) {
      ++m.segmented;
      const bool kind_ok = same_kind_as(g, detected_kinds[g_match[g]]);
      same_kind += kind_ok;
      m.recovered += kind_ok;
    }
  }
  for (int d = 0; d < D; ++d) {
    if (d_size[d] < min_fraction * N) continue;
    ++m.detected_counted;
    const int g = d_match[d];
    if (g >= 0 && iou(g, d) >= 0.5 && same_kind_as(g, detected_kinds[d])) ++m.precise;
  }
  m.recall = m.truth_counted ? static_cast<double>(m.recovered) / m.truth_counted : 0.0;
  m.precision = m.detected_counted ? static_cast<double>(m.precise) / m.detected_counted : 0.0;
  m.mean_iou = m.truth_counted ? m.mean_iou / m.truth_counted : 0.0;
  m.kind_accuracy = !truth_kinds  ? std::nan("")
                    : m.segmented ? static_cast<double>(same_kind) / m.segmented
                                  : 0.0;
  m.coverage = labelled ? static_cast<double>(covered) / labelled : 0.0;
  return m;
}

}  // namespace

SegmentationMetrics CompareSegmentations(const std::vector<int>& truth,
                                         const std::vector<NodeType>& truth_kinds,
                                         const std::vector<int>& detected,
                                         const std::vector<NodeType>& detected_kinds,
                                         double min_fraction) {
  return Compare(truth, static_cast<int>(truth_kinds.size()), &truth_kinds, detected,
                 detected_kinds, min_fraction);
}

SegmentationMetrics CompareSegmentationsWithoutKinds(const std::vector<int>& truth,
                                                     int truth_count,
                                                     const std::vector<int>& detected,
                                                     const std::vector<NodeType>& detected_kinds,
                                                     double min_fraction) {
  return Compare(truth, truth_count, nullptr, detected, detected_kinds, min_fraction);
}

}  // namespace implicitfit
