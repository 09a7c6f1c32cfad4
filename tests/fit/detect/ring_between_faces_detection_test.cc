// A cylinder ring two rows high between two faces (fit/detect/primitive_detector.h: the leftover
// pass, the band cylinder and the distance-then-normal re-assignment), rebuilt from the failure on
// Fit4CAD PC34 (a 261-point ring of radius 10.5, 0.75 high, at spacing 0.6, between a plane
// below and a spherical dome above). Generated like that CAD sample: a bottom annulus z = 0
// (6 <= r <= 10.2) on a square grid of step 0.6, the ring r = 10.5 as two rows of points (z = 0
// and z = 0.5, 0.48 apart along the circle), and a dome (sphere of radius 11.2 centred at
// z = -2.887) whose lowest row is the ring's top circle z = 1 (labelled sphere, as Fit4CAD's
// labeller does), rows 0.6 apart. Each point's label is the face it was placed on; normals are
// estimated from the points (PCA + MST) as for the Fit4CAD clouds. The ring's estimated normals
// are smeared by the faces beside it (no point of it has neighbours with agreeing normals), and
// its rows fit a sphere as well as a cylinder. Without the fix the ring goes to the plane
// (IoU 0.16) on every run; with it, a cylinder of radius 10.5 with IoU 0.50 (its points on the
// two joint rows, z = 0 and z = 1, lie on both neighbouring surfaces and are split by the normal).
// Not covered (measured): the same ring between two planes (a top disk z = 1 instead of the
// dome) still goes to the bottom plane.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "datasets/normals/neighbourhoods.h"
#include "datasets/normals/normal_estimation.h"
#include "fit/detect/primitive_detector.h"
#include "fit/detect/segmentation_metrics.h"
#include "support/detection.h"

namespace implicitfit {
namespace {

using Eigen::Vector3d;

constexpr double kRadius = 10.5, kGrid = 0.6, kDomeDepth = 2.887;

struct RingScene {
  PointCloud cloud;
  std::vector<int> labels;  // 0 bottom plane, 1 ring cylinder, 2 dome sphere
  std::vector<NodeType> kinds = {NodeType::kPlane, NodeType::kCylinder, NodeType::kSphere};
};

// `turn` rotates the grids about the axis (a different sample of the same part).
RingScene MakeRingScene(double turn) {
  RingScene s;
  auto add = [&](const Vector3d& p, int label) {
    s.cloud.points.push_back(p);
    s.labels.push_back(label);
  };
  const double c = std::cos(turn), si = std::sin(turn);
  for (double x = -kRadius; x <= kRadius; x += kGrid)
    for (double y = -kRadius; y <= kRadius; y += kGrid) {
      const Vector3d q(c * x - si * y, si * x + c * y, 0.0);
      const double r = q.norm();
      if (r >= 6.0 && r <= kRadius - 0.3) add(q, 0);
    }
  // The dome: rows of the sphere (centre (0, 0, -kDomeDepth), radius R, through the ring's top
  // circle z = 1, r = 10.5), kGrid apart along the meridians and around each row.
  const double big = std::hypot(kRadius, 1.0 + kDomeDepth);
  const double rim = std::asin(kRadius / big);  // polar angle of the joint row
  for (double phi = rim; phi > 0.5 * kGrid / big; phi -= kGrid / big) {
    const double rr = big * std::sin(phi), z = big * std::cos(phi) - kDomeDepth;
    const int count = static_cast<int>(std::lround(2 * M_PI * rr / kGrid));
    for (int k = 0; k < count; ++k) {
      const double a = turn + 2 * M_PI * (k + 0.5 * (phi != rim)) / count;
      add(Vector3d(rr * std::cos(a), rr * std::sin(a), z), 2);
    }
  }
  const int around = static_cast<int>(std::lround(2 * M_PI * kRadius / 0.48));
  for (double z : {0.0, 0.5})
    for (int k = 0; k < around; ++k) {
      const double a = turn + 2 * M_PI * k / around;
      add(Vector3d(kRadius * std::cos(a), kRadius * std::sin(a), z), 1);
    }
  EnsureOrientedNormals(&s.cloud);
  return s;
}

TEST(RingBetweenFacesDetection, TwoRowCylinderRingIsRecoveredAsACylinder) {
  int recovered = 0, runs = 0;
  for (double turn : {0.0, 0.1, 0.2})
    for (unsigned seed : {1u, 2u}) {
      const RingScene s = MakeRingScene(turn);
      DetectionOptions options;
      options.seed = seed;
      const DetectionResult r = testsupport::DetectCloud(s.cloud, options);
      const std::vector<NodeType> kinds = testsupport::KindsOf(r);
      const SegmentationMetrics m = CompareSegmentations(s.labels, s.kinds, r.labels, kinds);
      const int g = m.match[1];
      std::printf("turn %.1f seed %u: ring -> %s IoU %.2f, recall %d/%d precision %d/%d\n", turn,
                  seed, g >= 0 ? NodeTypeName(kinds[g]) : "-", m.iou[1], m.recovered,
                  m.truth_counted, m.precise, m.detected_counted);
      ++runs;
      if (std::getenv("RING_VERBOSE"))
        for (const auto& q : r.primitives) {
          std::printf("  %s %zu:", NodeTypeName(q.kind), q.points.size());
          for (double v : q.parameters) std::printf(" %.4g", v);
          std::printf("\n");
        }
      // Recovered: the detection sharing most of the ring's points is a cylinder with IoU >= 0.5,
      // whose axis is the z axis through the origin and whose radius is 10.5 (the generator's).
      if (g < 0 || kinds[g] != NodeType::kCylinder || m.iou[1] < 0.5) continue;
      const std::vector<double>& p = r.primitives[g].parameters;
      const Vector3d axis = Vector3d(p[3], p[4], p[5]).normalized();
      const Vector3d point(p[0], p[1], p[2]);
      EXPECT_GT(std::abs(axis.z()), 0.999);
      EXPECT_LT((point - point.dot(axis) * axis).norm(), 0.05);
      EXPECT_NEAR(p[6], kRadius, 0.05);
      ++recovered;
      // The two faces are recovered too.
      EXPECT_EQ(m.recovered, 3);
    }
  EXPECT_EQ(recovered, runs);
}

}  // namespace
}  // namespace implicitfit
