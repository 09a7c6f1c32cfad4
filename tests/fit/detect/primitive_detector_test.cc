// Detection of every primitive in a cloud (fit/detect/primitive_detector.h), judged against the
// known truth of generated scenes (datasets/generators/scene_generator.h) and of the Fit4CAD and
// CGAL labelled clouds, with the metrics of fit/detect/segmentation_metrics.h.
#include "fit/detect/primitive_detector.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <random>
#include <string>

#include "datasets/clouds/cloud_file.h"
#include "datasets/clouds/cloud_file_info.h"
#include "datasets/generators/ground_truth.h"
#include "datasets/generators/scene_generator.h"
#include "datasets/normals/neighbourhoods.h"
#include "datasets/normals/normal_estimation.h"
#include "fit/detect/segmentation_metrics.h"
#include "support/detection.h"

namespace implicitfit {
namespace {

using testsupport::DetectCloud;
using testsupport::KindsOf;

// With IMPLICITFIT_DETECT_VERBOSE set: each ground-truth primitive, its match and IoU.
void Describe(const std::vector<int>& labels, const std::vector<NodeType>& kinds,
              const DetectionResult& r, const SegmentationMetrics& m) {
  if (!std::getenv("IMPLICITFIT_DETECT_VERBOSE")) return;
  std::vector<int> size(kinds.size(), 0);
  for (int l : labels)
    if (l >= 0) ++size[l];
  std::printf("  tau %.4g spacing %.4g noise %.4g theta %.1f, %zu detected\n", r.threshold,
              r.spacing, r.noise, r.normal_angle_deg, r.primitives.size());
  for (size_t g = 0; g < kinds.size(); ++g)
    std::printf("  truth %zu %s %d -> %d %s %d IoU %.2f\n", g, NodeTypeName(kinds[g]), size[g],
                m.match[g], m.match[g] >= 0 ? NodeTypeName(r.primitives[m.match[g]].kind) : "-",
                m.match[g] >= 0 ? static_cast<int>(r.primitives[m.match[g]].points.size()) : 0,
                m.iou[g]);
  for (size_t d = 0; d < r.primitives.size(); ++d) {
    std::printf("  detected %zu %s %zu rms %.3g:", d, NodeTypeName(r.primitives[d].kind),
                r.primitives[d].points.size(), r.primitives[d].rms_distance);
    for (double v : r.primitives[d].parameters) std::printf(" %.4g", v);
    std::printf("\n");
  }
}

SegmentationMetrics Score(const GeneratedScene& scene, const DetectionResult& r) {
  const SegmentationMetrics m =
      CompareSegmentations(scene.labels, scene.kinds, r.labels, KindsOf(r));
  Describe(scene.labels, scene.kinds, r, m);
  return m;
}

// Labels consistent with the primitive lists, every point of a primitive labelled with it.
void ExpectConsistent(const DetectionResult& r, size_t n) {
  ASSERT_EQ(r.labels.size(), n);
  std::vector<int> count(r.primitives.size(), 0);
  for (int l : r.labels) {
    ASSERT_GE(l, -1);
    ASSERT_LT(l, static_cast<int>(r.primitives.size()));
    if (l >= 0) ++count[l];
  }
  for (size_t k = 0; k < r.primitives.size(); ++k) {
    EXPECT_EQ(count[k], static_cast<int>(r.primitives[k].points.size()));
    for (int i : r.primitives[k].points) EXPECT_EQ(r.labels[i], static_cast<int>(k));
  }
}

TEST(PrimitiveDetector, GeneratedScenesAreRecoveredOnManySeeds) {
  int truth = 0, recovered = 0, detected = 0, precise = 0;
  for (unsigned seed = 1; seed <= 8; ++seed) {
    GeneratedSceneOptions o;
    o.seed = seed;
    const GeneratedScene scene = GenerateScene(o);
    DetectionOptions d;
    d.seed = seed;
    const DetectionResult r = DetectCloud(scene.cloud, d);
    ExpectConsistent(r, scene.cloud.size());
    const SegmentationMetrics m = Score(scene, r);
    EXPECT_GE(m.recall, 5.0 / 6.0) << "seed " << seed;  // at most one of six primitives missed
    truth += m.truth_counted, recovered += m.recovered;
    detected += m.detected_counted, precise += m.precise;
  }
  EXPECT_GE(static_cast<double>(recovered) / truth, 0.95);
  EXPECT_GE(static_cast<double>(precise) / detected, 0.9);
}

TEST(PrimitiveDetector, RecoveredParametersAreCloseToTheTruth) {
  GeneratedSceneOptions o;
  o.seed = 3;
  const GeneratedScene scene = GenerateScene(o);
  const DetectionResult r = DetectCloud(scene.cloud);
  const SegmentationMetrics m = Score(scene, r);
  for (size_t g = 0; g < scene.models.size(); ++g) {
    ASSERT_GE(m.match[g], 0);
    const DetectedPrimitive& p = r.primitives[m.match[g]];
    ASSERT_EQ(p.kind, scene.kinds[g]);
    // The detected surface passes through the truth's noise-free samples: RMS of the detected f
    // over points drawn on the true model, well under the noise (0.005) plus a margin.
    Model detected;
    detected.AddPrimitive(p.kind, p.parameters);
    double ss = 0;
    int n = 0;
    for (size_t i = 0; i < scene.labels.size(); ++i) {
      if (scene.labels[i] != static_cast<int>(g)) continue;
      // Project the noisy point back onto the true surface along its (true) normal.
      const Eigen::Vector3d x = scene.cloud.points[i];
      const double f_true = scene.models[g].Value(x);
      const Eigen::Vector3d on = x - f_true * scene.cloud.normals[i];
      const double f = detected.Value(on);
      ss += f * f, ++n;
    }
    EXPECT_LT(std::sqrt(ss / n), 0.004) << NodeTypeName(scene.kinds[g]);
  }
}

TEST(PrimitiveDetector, PlaneOnlySceneGivesOnlyPlanes) {
  for (unsigned seed = 1; seed <= 3; ++seed) {
    GeneratedSceneOptions o;
    o.seed = seed;
    o.planes_only = true;
    const GeneratedScene scene = GenerateScene(o);
    const DetectionResult r = DetectCloud(scene.cloud);
    ASSERT_FALSE(r.primitives.empty());
    for (const auto& p : r.primitives) EXPECT_EQ(p.kind, NodeType::kPlane) << "seed " << seed;
    const SegmentationMetrics m = Score(scene, r);
    EXPECT_EQ(m.recovered, 6) << "seed " << seed;
  }
}

TEST(PrimitiveDetector, IcosahedronGivesTwentyPlanes) {
  GeneratedSceneOptions o;
  o.object_points = 500;
  o.noise = 0.002;
  const GeneratedScene scene = GenerateIcosahedron(o);
  ASSERT_EQ(scene.models.size(), 20u);
  const DetectionResult r = DetectCloud(scene.cloud);
  const SegmentationMetrics m = Score(scene, r);
  EXPECT_EQ(r.primitives.size(), 20u);
  for (const auto& p : r.primitives) EXPECT_EQ(p.kind, NodeType::kPlane);
  EXPECT_EQ(m.recovered, 20);
  for (const auto& p : r.primitives) EXPECT_EQ(p.normal_side, "outward");
}

TEST(PrimitiveDetector, SameResultForOneAndTwoThreads) {
  GeneratedSceneOptions o;
  o.seed = 5;
  const GeneratedScene scene = GenerateScene(o);
  DetectionOptions one, two;
  one.num_threads = 1;
  two.num_threads = 2;
  const DetectionResult a = DetectCloud(scene.cloud, one), b = DetectCloud(scene.cloud, two);
  ASSERT_EQ(a.primitives.size(), b.primitives.size());
  EXPECT_EQ(a.labels, b.labels);
  for (size_t k = 0; k < a.primitives.size(); ++k) {
    EXPECT_EQ(a.primitives[k].kind, b.primitives[k].kind);
    EXPECT_EQ(a.primitives[k].parameters, b.primitives[k].parameters);  // bitwise
  }
}

TEST(PrimitiveDetector, RandomPointsGiveNoPrimitive) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1, 1);
  std::normal_distribution<double> g;
  PointCloud cloud;
  for (int i = 0; i < 3000; ++i) {
    cloud.points.emplace_back(u(rng), u(rng), u(rng));
    cloud.normals.push_back(Eigen::Vector3d(g(rng), g(rng), g(rng)).normalized());
  }
  const DetectionResult r = DetectCloud(cloud);
  EXPECT_TRUE(r.primitives.empty())
      << r.primitives.size() << " primitives, first " << NodeTypeName(r.primitives[0].kind)
      << " with " << r.primitives[0].points.size() << " points";
}

TEST(PrimitiveDetector, InvalidInputsAreRefused) {
  PointCloud cloud;
  cloud.points = {Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitX()};
  cloud.normals = {Eigen::Vector3d::UnitZ()};
  EXPECT_THROW(DetectPrimitives(cloud.points, cloud.normals, {{1}, {0}}, 1.0),
               std::invalid_argument);
  cloud.normals.push_back(Eigen::Vector3d::UnitZ());
  EXPECT_THROW(DetectPrimitives(cloud.points, cloud.normals, {{1}, {5}}, 1.0),
               std::invalid_argument);
  DetectionOptions bad;
  bad.kinds = {NodeType::kUnion};
  EXPECT_THROW(DetectPrimitives(cloud.points, cloud.normals, {{1}, {0}}, 1.0, bad),
               std::invalid_argument);
}

// Fit4CAD (GPL-3, read from ../shared/data only): noise-free CAD parts, no normals (estimated
// and MST-oriented, as a user's run would), per-point labels and primitive kinds.
TEST(PrimitiveDetector, Fit4CadRecall) {
  const std::string root = std::string(IMPLICITFIT_SHARED_DATA) + "/fit4cad/";
  const std::vector<std::string> names = {"test_PC33",   "test_PC34",   "test_PC35",
                                          "test_PC21",   "train_PC124", "train_PC131",
                                          "train_PC145", "train_PC155"};
  if (!std::ifstream(root + "fit4cad_test_PC33.xyzl")) GTEST_SKIP() << "no " << root;
  int truth = 0, recovered = 0;
  for (const std::string& name : names) {
    CloudFileInfo info;
    PointCloud cloud = ReadCloudFile(root + "fit4cad_" + name + ".xyzl", &info);
    EnsureOrientedNormals(&cloud);
    std::vector<int> labels = info.labels;
    for (int& l : labels) l -= 1;
    const std::vector<NodeType> kinds =
        ReadFit4CadKinds(root + "fit4cad_" + name + "/" + name + "_implicit.txt");
    const DetectionResult r = DetectCloud(cloud);
    const SegmentationMetrics m = CompareSegmentations(labels, kinds, r.labels, KindsOf(r));
    Describe(labels, kinds, r, m);
    std::printf("%s: recall %d/%d precision %d/%d mean IoU %.2f\n", name.c_str(), m.recovered,
                m.truth_counted, m.precise, m.detected_counted, m.mean_iou);
    truth += m.truth_counted, recovered += m.recovered;
  }
  // 2026-12-02: 52 of 54 (missed: PC21's chamfer ring, PC155's face coplanar with another;
  // PC33's one-row cylinder ring since its halves within a spacing are joined); 51 before; 50
  // before the leftover pass found PC34's two-row ring; 47 with the tangent-plane noise.
  EXPECT_EQ(truth, 54);
  EXPECT_GE(recovered, 52);
}

// PC33's cylinder ring (r 5.5, 0.4 high, 143 of 1 500 points, between a sphere and a plane):
// its points' nearest neighbours lie on the faces beside it, so over the neighbour graph the
// ring fell into two halves 0.26 apart (spacing 0.50) and the smaller was dropped (IoU 0.49).
// Truth from the file's labels: the ring is one support of a cylinder of radius 5.5.
TEST(PrimitiveDetector, Fit4CadPc33NarrowRingIsOneSupport) {
  const std::string path = std::string(IMPLICITFIT_SHARED_DATA) + "/fit4cad/fit4cad_test_PC33.xyzl";
  if (!std::ifstream(path)) GTEST_SKIP() << "no " << path;
  CloudFileInfo info;
  PointCloud cloud = ReadCloudFile(path, &info);
  EnsureOrientedNormals(&cloud);
  const DetectionResult r = DetectCloud(cloud);
  int ring = 0;
  for (int l : info.labels) ring += l == 2;
  ASSERT_EQ(ring, 143);
  bool found = false;
  for (size_t k = 0; k < r.primitives.size(); ++k) {
    const DetectedPrimitive& p = r.primitives[k];
    if (p.kind != NodeType::kCylinder) continue;
    found = true;
    EXPECT_NEAR(p.parameters[6], 5.5, 0.055);  // point (3), axis (3), radius
    int on_ring = 0, off_surface = 0;
    for (int i : p.points) {
      on_ring += info.labels[i] == 2;
      // The truth's cylinder: x^2 + y^2 = 5.5^2 (the file's implicit equation). Points of the
      // faces beside it on their common edges are on it too.
      const Eigen::Vector3d& x = cloud.points[i];
      off_surface += std::abs(std::hypot(x.x(), x.y()) - 5.5) > 0.06;
    }
    EXPECT_GE(on_ring, 0.9 * ring) << p.points.size() << " points";
    EXPECT_EQ(off_surface, 0);
  }
  EXPECT_TRUE(found);
}

TEST(PrimitiveDetector, CgalIcosahedronFaces) {
  const std::string path =
      std::string(IMPLICITFIT_SHARED_DATA) + "/cgal/cgal_ball_icosahedron_20planes_labeled.ply";
  if (!std::ifstream(path)) GTEST_SKIP() << "no " << path;
  const PointCloud cloud = ReadCloudFile(path);
  const std::vector<int> labels = ReadPlyIntProperty(path, "segment_index");
  const DetectionResult r = DetectCloud(cloud);
  const SegmentationMetrics m = CompareSegmentations(
      labels, std::vector<NodeType>(20, NodeType::kPlane), r.labels, KindsOf(r));
  Describe(labels, std::vector<NodeType>(20, NodeType::kPlane), r, m);
  EXPECT_GE(m.recovered, 19);
  EXPECT_GE(m.precision, 0.9);
}

}  // namespace
}  // namespace implicitfit
