// fit/detect/segmentation_metrics.h on small hand-made segmentations whose figures are counted by hand.
#include "fit/detect/segmentation_metrics.h"

#include <gtest/gtest.h>

namespace implicitfit {
namespace {

const NodeType P = NodeType::kPlane, S = NodeType::kSphere, C = NodeType::kCylinder;

TEST(SegmentationMetrics, CountsByHand) {
  // Truth: g0 = points 0..9 (plane), g1 = 10..17 (sphere), g2 = 18..19 (cylinder, 2 of 20 points).
  std::vector<int> truth(20);
  for (int i = 0; i < 20; ++i) truth[i] = i < 10 ? 0 : i < 18 ? 1 : 2;
  // Detected: d0 = 0..7 (plane), d1 = 8..13 (sphere), 14..19 unassigned.
  std::vector<int> detected(20, -1);
  for (int i = 0; i < 14; ++i) detected[i] = i < 8 ? 0 : 1;
  const SegmentationMetrics m = CompareSegmentations(truth, {P, S, C}, detected, {P, S}, 0.15);
  // Counted truth: g0 (10), g1 (8); g2 holds 10% < 15%.
  EXPECT_EQ(m.truth_counted, 2);
  // g0 -> d0: IoU 8/10; g1 -> d1 (4 shared, d1 has 6): IoU 4 / (8 + 6 - 4) = 0.4.
  EXPECT_EQ(m.match[0], 0);
  EXPECT_EQ(m.match[1], 1);
  EXPECT_EQ(m.match[2], -1);
  EXPECT_DOUBLE_EQ(m.iou[0], 0.8);
  EXPECT_DOUBLE_EQ(m.iou[1], 0.4);
  EXPECT_EQ(m.recovered, 1);
  EXPECT_DOUBLE_EQ(m.recall, 0.5);
  EXPECT_DOUBLE_EQ(m.mean_iou, 0.6);
  // d0 (8 points) matches g0; d1 (6 points) overlaps g0 by 2 and g1 by 4 -> g1, IoU 0.4.
  EXPECT_EQ(m.detected_counted, 2);
  EXPECT_EQ(m.precise, 1);
  EXPECT_EQ(m.segmented, 1);
  EXPECT_DOUBLE_EQ(m.kind_accuracy, 1.0);
  EXPECT_DOUBLE_EQ(m.coverage, 14.0 / 20.0);
}

TEST(SegmentationMetrics, WrongKindIsNotRecovered) {
  const std::vector<int> truth = {0, 0, 0, 0, 1, 1, 1, 1};
  const std::vector<int> detected = {0, 0, 0, 0, 1, 1, 1, -1};
  const SegmentationMetrics m = CompareSegmentations(truth, {P, C}, detected, {P, S});
  EXPECT_EQ(m.segmented, 2);  // g1 -> d1, IoU 3/4
  EXPECT_EQ(m.recovered, 1);
  EXPECT_DOUBLE_EQ(m.kind_accuracy, 0.5);
  EXPECT_DOUBLE_EQ(m.precision, 0.5);
}

TEST(SegmentationMetrics, MismatchedInputsThrow) {
  EXPECT_THROW(CompareSegmentations({0, 0}, {P}, {0}, {P}), std::invalid_argument);
  EXPECT_THROW(CompareSegmentations({0, 3}, {P}, {0, 0}, {P}), std::invalid_argument);
}

}  // namespace
}  // namespace implicitfit
