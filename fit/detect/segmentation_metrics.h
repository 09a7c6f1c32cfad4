// Figures of a detected segmentation against ground truth (tests and bench/ use this one code):
// both are per-point labels (-1 = none, else an index into their primitive list) with a kind per
// primitive. Counted primitives hold at least min_fraction of the N points.
//   match(g)     the detected primitive sharing most points with ground-truth primitive g;
//   IoU(g, d)    |g ∩ d| / |g ∪ d| over point sets;
//   recall       counted ground-truth primitives g with IoU(g, match(g)) >= 0.5 and the same kind,
//                over the counted ground-truth primitives;
//   precision    counted detected primitives d whose most-overlapping ground-truth primitive g
//                has IoU >= 0.5 and the same kind, over the counted detected primitives;
//   mean IoU     mean of IoU(g, match(g)) over the counted ground-truth primitives (0 unmatched);
//   kind accuracy  among counted ground-truth primitives with IoU(g, match(g)) >= 0.5, the
//                fraction whose match has the same kind (segmentation right, is the kind?);
//   coverage     ground-truth labelled points assigned to some detected primitive, over them.
// Without truth kinds (a labelled scan that does not say what each segment is), recall and
// precision ask IoU >= 0.5 only, and kind accuracy is NaN.
#pragma once

#include <vector>

#include "model/model.h"

namespace implicitfit {

struct SegmentationMetrics {
  int truth_counted = 0, detected_counted = 0;
  int recovered = 0;  // counted ground truth matched (IoU >= 0.5, same kind)
  int precise = 0;    // counted detections matched
  int segmented = 0;  // counted ground truth with IoU(g, match(g)) >= 0.5
  double recall = 0.0, precision = 0.0, mean_iou = 0.0, kind_accuracy = 0.0, coverage = 0.0;
  std::vector<int> match;   // per ground-truth primitive: match(g) or -1
  std::vector<double> iou;  // per ground-truth primitive: IoU(g, match(g))
};

// Throws std::invalid_argument when the label vectors differ in length or a label is out of range.
SegmentationMetrics CompareSegmentations(const std::vector<int>& truth_labels,
                                         const std::vector<NodeType>& truth_kinds,
                                         const std::vector<int>& detected_labels,
                                         const std::vector<NodeType>& detected_kinds,
                                         double min_fraction = 0.01);
// The same when the truth's kinds are not known: `truth_count` primitives, labels 0..count-1.
SegmentationMetrics CompareSegmentationsWithoutKinds(const std::vector<int>& truth_labels,
                                                     int truth_count,
                                                     const std::vector<int>& detected_labels,
                                                     const std::vector<NodeType>& detected_kinds,
                                                     double min_fraction = 0.01);

}  // namespace implicitfit
