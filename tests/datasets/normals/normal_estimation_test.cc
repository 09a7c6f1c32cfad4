// Normal estimation and orientation, judged against ground truth (exact sphere normals, brute
// force neighbour search) and, on real scans, against the scanner viewpoint.
#include "datasets/normals/normal_estimation.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "datasets/clouds/cloud_file.h"
#include "datasets/normals/normal_orientation.h"
#include "support/fibonacci_sphere.h"
#include "support/run_command.h"

namespace implicitfit {
namespace {

// Fibonacci-spiral samples of a sphere, with their exact outward normals.
PointCloud Sphere(const Eigen::Vector3d& centre, double radius, int count) {
  PointCloud c;
  for (const Eigen::Vector3d& n : testsupport::FibonacciSphere(count)) {
    c.points.push_back(centre + radius * n);
    c.normals.push_back(n);
  }
  return c;
}

void RandomiseSigns(PointCloud* c, unsigned seed) {
  std::mt19937 rng(seed);
  for (Eigen::Vector3d& n : c->normals)
    if (rng() & 1) n = -n;
}

// Fraction of normals within `degrees` of the truth, sign included.
double Agreeing(const std::vector<Eigen::Vector3d>& normals,
                const std::vector<Eigen::Vector3d>& truth, double degrees) {
  const double c = std::cos(degrees * M_PI / 180.0);
  size_t ok = 0;
  for (size_t i = 0; i < truth.size(); ++i) ok += normals[i].dot(truth[i]) >= c;
  return static_cast<double>(ok) / static_cast<double>(truth.size());
}

TEST(Neighbourhoods, AreTheNearestPointsByBruteForce) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<Eigen::Vector3d> points(400);
  for (auto& p : points)
    p = Eigen::Vector3d(u(rng), u(rng), 0.05 * u(rng)) + Eigen::Vector3d(5e5, 4e6, 100);
  const Neighbourhoods nb = FindNeighbourhoods(points);
  for (size_t i = 0; i < points.size(); ++i) {
    std::vector<std::pair<double, int>> all;
    for (size_t j = 0; j < points.size(); ++j)
      if (j != i) all.push_back({(points[j] - points[i]).norm(), static_cast<int>(j)});
    std::sort(all.begin(), all.end());
    const NeighbourGraph::Row mine = nb.indices[i];
    ASSERT_GE(mine.size(), 8u);
    ASSERT_LE(mine.size(), 30u);
    for (size_t k = 0; k < mine.size(); ++k) EXPECT_EQ(mine[k], all[k].second) << i << " " << k;
    // k follows density: every neighbour within the radius is taken, up to max_k.
    if (mine.size() < 30 && mine.size() > 8) {
      EXPECT_GT(all[mine.size()].first, nb.radius);
    }
  }
}

// Duplicates are searched once (a k-d tree cannot split equal points) but the neighbourhoods
// are still the nearest points by brute force: distances equal rank by rank (ties between
// copies may come in any order), copies of a point first.
TEST(Neighbourhoods, DuplicatesGiveTheBruteForceNeighbourhoods) {
  std::mt19937 rng(12);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<Eigen::Vector3d> points;
  for (int i = 0; i < 150; ++i) {
    const Eigen::Vector3d p(u(rng), u(rng), 0.05 * u(rng));
    const int copies = i % 5 == 0 ? 1 + static_cast<int>(rng() % 40) : 0;  // some 1..40 times
    for (int c = 0; c <= copies; ++c) points.push_back(p);
  }
  std::shuffle(points.begin(), points.end(), rng);
  const Neighbourhoods nb = FindNeighbourhoods(points);
  size_t duplicates = 0;
  for (size_t i = 0; i < points.size(); ++i)
    for (size_t j = 0; j < i; ++j)
      if (points[j] == points[i]) {
        ++duplicates;
        break;
      }
  EXPECT_EQ(nb.duplicates, duplicates);
  for (size_t i = 0; i < points.size(); ++i) {
    std::vector<double> all;
    for (size_t j = 0; j < points.size(); ++j)
      if (j != i) all.push_back((points[j] - points[i]).norm());
    std::sort(all.begin(), all.end());
    const NeighbourGraph::Row mine = nb.indices[i];
    ASSERT_GE(mine.size(), 8u);
    ASSERT_LE(mine.size(), 30u);
    for (size_t k = 0; k < mine.size(); ++k) {
      ASSERT_NE(mine[k], static_cast<int>(i));
      EXPECT_NEAR((points[mine[k]] - points[i]).norm(), all[k], 1e-12) << i << " " << k;
    }
  }
  // 50 000 copies of one point: near-linear (it took 22 s through the command line at 80 000).
  const std::vector<Eigen::Vector3d> same(50000, Eigen::Vector3d(1, 2, 3));
  const Neighbourhoods one = FindNeighbourhoods(same);
  EXPECT_EQ(one.duplicates, 49999u);
  EXPECT_EQ(one.indices[123].size(), 30u);  // max_k copies, all within the radius 0
  EXPECT_EQ(one.spacing, 0.0);
}

TEST(NormalOrientation, RandomSignsOnSpheresAreDetectedAndReoriented) {
  for (unsigned seed = 1; seed <= 5; ++seed) {
    // Two spheres far apart: two components, each seeded separately.
    PointCloud truth = Sphere({0.2, -1, 3}, 1.3, 2000);
    const PointCloud second = Sphere({-6, 2, 0}, 0.5, 600);
    truth.points.insert(truth.points.end(), second.points.begin(), second.points.end());
    truth.normals.insert(truth.normals.end(), second.normals.begin(), second.normals.end());
    PointCloud cloud = truth;
    RandomiseSigns(&cloud, seed);
    const NormalResult r = EnsureOrientedNormals(&cloud);
    EXPECT_EQ(r.action, "read from file, MST-re-oriented");
    EXPECT_GT(r.opposed_fraction, 0.4);
    EXPECT_GT(Agreeing(cloud.normals, truth.normals, 1e-3), 0.99) << "seed " << seed;
  }
}

TEST(NormalOrientation, ConsistentFileNormalsAreKept) {
  PointCloud cloud = Sphere({1, 2, 3}, 2.0, 1500);
  const PointCloud truth = cloud;
  const NormalResult r = EnsureOrientedNormals(&cloud);
  EXPECT_EQ(r.action, "read from file");
  EXPECT_EQ(r.flipped, 0u);
  EXPECT_LT(r.opposed_fraction, 0.001);
  EXPECT_EQ(cloud.normals, truth.normals);
}

TEST(NormalEstimation, MissingNormalsAreEstimatedAndOrientedOutward) {
  const PointCloud truth = Sphere({0.5, 0.5, -2}, 0.8, 3000);
  PointCloud cloud;
  cloud.points = truth.points;
  const NormalResult r = EnsureOrientedNormals(&cloud);
  EXPECT_EQ(r.action, "estimated, MST-oriented");
  EXPECT_EQ(r.estimated, 3000u);
  EXPECT_GE(r.mean_neighbours, 8.0);
  EXPECT_GT(Agreeing(cloud.normals, truth.normals, 5.0), 0.99);
}

TEST(NormalEstimation, NoisyFarAwaySphereStillOrientsOutward) {
  // UTM-like offset and 0.5% noise: recentring keeps the PCA accurate.
  PointCloud truth = Sphere({4.2e5, 5.1e6, 250}, 3.0, 4000);
  std::mt19937 rng(5);
  std::normal_distribution<double> g(0.0, 0.015);
  PointCloud cloud;
  for (const Eigen::Vector3d& p : truth.points)
    cloud.points.push_back(p + Eigen::Vector3d(g(rng), g(rng), g(rng)));
  EnsureOrientedNormals(&cloud);
  EXPECT_GT(Agreeing(cloud.normals, truth.normals, 90.0), 0.99);  // sign
  EXPECT_GT(Agreeing(cloud.normals, truth.normals, 15.0), 0.95);  // direction
}

TEST(NormalEstimation, ViewpointOrientsEveryNormalTowardTheSensor) {
  // A wavy height field seen from above.
  PointCloud cloud;
  for (int i = 0; i < 40; ++i)
    for (int j = 0; j < 40; ++j) {
      const double x = i * 0.05, y = j * 0.05;
      cloud.points.emplace_back(x, y, 0.1 * std::sin(3 * x) * std::cos(2 * y));
    }
  NormalOptions options;
  options.viewpoint = Eigen::Vector3d(1, 1, 4);
  const NormalResult r = EnsureOrientedNormals(&cloud, options);
  EXPECT_EQ(r.action, "estimated, oriented toward viewpoint");
  for (size_t i = 0; i < cloud.size(); ++i) {
    // Truth: the upward normal of z = h(x, y) is (-h_x, -h_y, 1).
    const double x = cloud.points[i].x(), y = cloud.points[i].y();
    const Eigen::Vector3d up = Eigen::Vector3d(-0.3 * std::cos(3 * x) * std::cos(2 * y),
                                               0.2 * std::sin(3 * x) * std::sin(2 * y), 1)
                                   .normalized();
    EXPECT_GT(cloud.normals[i].dot(up), std::cos(10 * M_PI / 180)) << i;
  }
}

TEST(NormalOrientation, DetectorSeparatesOrientedFromRandomSigns) {
  PointCloud cloud = Sphere({0, 0, 0}, 1.0, 2000);
  const Neighbourhoods nb = FindNeighbourhoods(cloud.points);
  EXPECT_LT(OpposedNeighbourFraction(cloud.normals, nb.indices), 0.001);
  RandomiseSigns(&cloud, 9);
  const double random = OpposedNeighbourFraction(cloud.normals, nb.indices);
  EXPECT_GT(random, 0.4);
  EXPECT_LT(random, 0.6);
}

TEST(NormalEstimation, InvalidFileNormalsAreReestimatedFromNeighbours) {
  const std::string dir = testsupport::ScratchDir("invalid_normals");
  std::string text;
  for (int i = 0; i < 10; ++i)
    for (int j = 0; j < 10; ++j)
      text += std::to_string(i) + " " + std::to_string(j) + " 0 " +
              (i == 4 && j == 5 ? "0 0 0" : "0 0 -1") + "\n";
  testsupport::WriteText(dir + "/plane.xyz", text);
  CloudFileInfo info;
  const PointCloud cloud = ReadCloudFile(dir + "/plane.xyz", &info);
  ASSERT_EQ(info.invalid_normals, std::vector<size_t>{45});
  EXPECT_LT((cloud.normals[45] - Eigen::Vector3d(0, 0, -1)).norm(), 1e-9);
}

}  // namespace
}  // namespace implicitfit
