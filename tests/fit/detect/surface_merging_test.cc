// The detector's final "one surface or two" (fit/detect/surface_merging.h) on generated planes
// whose truth is known by construction: a plane sampled with a density that varies 10 times
// across it and 0.5% noise is one primitive; two parallel sheets 5 sigma apart stay two.
// Normals are estimated (PCA + orientation), as on a user's raw scan.
#include <gtest/gtest.h>

#include <random>

#include "datasets/clouds/point_cloud.h"
#include "datasets/normals/neighbourhoods.h"
#include "datasets/normals/normal_estimation.h"
#include "fit/detect/primitive_detector.h"
#include "fit/detect/segmentation_metrics.h"
#include "support/detection.h"

namespace implicitfit {
namespace {

DetectionResult Detect(PointCloud* cloud) {
  EnsureOrientedNormals(cloud);
  return testsupport::DetectCloud(*cloud);
}

// n points uniform on [x0, x1] x [0, 1] at height z, Gaussian noise sigma along z.
void AddSheet(PointCloud* cloud, std::vector<int>* labels, int label, int n, double x0, double x1,
              double z, double sigma, std::mt19937* rng) {
  std::uniform_real_distribution<double> ux(x0, x1), uy(0.0, 1.0);
  std::normal_distribution<double> noise(0.0, sigma);
  for (int i = 0; i < n; ++i) {
    cloud->points.emplace_back(ux(*rng), uy(*rng), z + noise(*rng));
    labels->push_back(label);
  }
}

TEST(SurfaceMerging, PlaneWithDensityVaryingTenTimesIsOnePrimitive) {
  // [0, 1] x [0, 1]: the left half 10 times denser than the right; noise 0.5% of the side.
  std::mt19937 rng(7);
  PointCloud cloud;
  std::vector<int> labels;
  AddSheet(&cloud, &labels, 0, 10000, 0.0, 0.5, 0.0, 0.005, &rng);
  AddSheet(&cloud, &labels, 0, 1000, 0.5, 1.0, 0.0, 0.005, &rng);
  const DetectionResult r = Detect(&cloud);
  int counted = 0;
  for (const auto& p : r.primitives) counted += p.points.size() >= cloud.size() / 100;
  EXPECT_EQ(counted, 1) << r.primitives.size() << " primitives in all";
  ASSERT_FALSE(r.primitives.empty());
  const SegmentationMetrics m =
      CompareSegmentations(labels, {NodeType::kPlane}, r.labels, {r.primitives[0].kind});
  EXPECT_EQ(m.recovered, 1);
  EXPECT_GE(m.iou[0], 0.9);
  // Both halves belong to it, the sparse one too.
  int sparse = 0;
  for (size_t i = 10000; i < cloud.size(); ++i) sparse += r.labels[i] == m.match[0];
  EXPECT_GE(sparse, 900);
}

TEST(SurfaceMerging, TwoParallelSheetsFiveSigmaApartStayTwo) {
  const double sigma = 0.001;
  std::mt19937 rng(11);
  PointCloud cloud;
  std::vector<int> labels;
  AddSheet(&cloud, &labels, 0, 4000, 0.0, 1.0, 0.0, sigma, &rng);
  AddSheet(&cloud, &labels, 1, 4000, 0.0, 1.0, 5 * sigma, sigma, &rng);
  const DetectionResult r = Detect(&cloud);
  const std::vector<NodeType> kinds = testsupport::KindsOf(r);
  const SegmentationMetrics m =
      CompareSegmentations(labels, {NodeType::kPlane, NodeType::kPlane}, r.labels, kinds);
  EXPECT_EQ(m.recovered, 2) << r.primitives.size() << " primitives";
  EXPECT_NE(m.match[0], m.match[1]);
}

}  // namespace
}  // namespace implicitfit
