// The curvature-free noise estimate (fit/detect/surface_noise.h) and its use by the detector
// (fit/detect/primitive_detector.h), on generated surfaces with known noise. Expected values:
//   - a sphere: (n_i + n_j) / 2 . (p_j - p_i) = (|p_j|^2 - |p_i|^2) / (2 R) = 0 exactly (centre at
//     the origin, n = p / R), whatever the spacing;
//   - Gaussian offsets e ~ N(0, s^2) along exact normals: the mid-normal distance of two points is
//     e_j - e_i (to first order), a N(0, 2 s^2) variable, so the MAD figure reads about sqrt(2) s
//     (the median over a point's neighbours shares e_i, which spreads the figure: [1.1, 1.7] s);
//   - the tangent-plane distance n_i . (p_j - p_i) (computed here, as the detector did before)
//     also holds the sagitta d^2 / (2 R) of a neighbour at distance d.
#include "fit/detect/surface_noise.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "datasets/normals/neighbourhoods.h"
#include "fit/detect/primitive_detector.h"
#include "model/median.h"
#include "support/fibonacci_sphere.h"

namespace implicitfit {
namespace {

using Eigen::Vector3d;

struct Sample {
  std::vector<Vector3d> points, normals;
};

// Evenly spread points on a sphere of radius r centred at the origin (Fibonacci lattice).
Sample Sphere(int n, double r) {
  Sample s;
  for (const Vector3d& u : testsupport::FibonacciSphere(n)) {
    s.points.push_back(r * u);
    s.normals.push_back(u);
  }
  return s;
}

// A cylinder of radius r (axis z, height h) on a regular grid of step `step`, each point moved
// along the exact normal by N(0, noise^2).
Sample NoisyCylinder(double r, double h, double step, double noise, unsigned seed) {
  Sample s;
  std::mt19937 rng(seed);
  std::normal_distribution<double> g(0.0, noise);
  const int around = static_cast<int>(std::round(2 * M_PI * r / step));
  for (int k = 0; k * step <= h; ++k)
    for (int a = 0; a < around; ++a) {
      const double t = 2 * M_PI * a / around;
      const Vector3d n(std::cos(t), std::sin(t), 0.0);
      s.points.push_back(r * n + Vector3d(0, 0, k * step) + g(rng) * n);
      s.normals.push_back(n);
    }
  return s;
}

// The detector's former figure: 1.4826 median over points of the median over their first 8
// neighbours of the distance to the point's tangent plane.
double TangentPlaneNoise(const Sample& s, const NeighbourGraph& nb) {
  std::vector<double> figures;
  for (size_t i = 0; i < s.points.size(); ++i) {
    std::vector<double> d;
    for (size_t k = 0; k < std::min<size_t>(8, nb[i].size()); ++k)
      d.push_back(std::abs(s.normals[i].dot(s.points[nb[i][k]] - s.points[i])));
    figures.push_back(Median(d));
  }
  return 1.4826 * Median(figures);
}

TEST(SurfaceNoise, NoiseFreeCoarseSphereReadsZero) {
  // 600 points on radius 12.7: spacing about 1.8, the coarseness of Fit4CAD PC21.
  const Sample s = Sphere(600, 12.7);
  const Neighbourhoods nb = FindNeighbourhoods(s.points);
  EXPECT_LT(EstimateSurfaceNoise(s.points, s.normals, nb.indices), 1e-9);
  // The tangent-plane figure reads the sagitta (d ~ 1.5 .. 2.5: 0.09 .. 0.25, times 1.4826).
  EXPECT_GT(TangentPlaneNoise(s, nb.indices), 0.1);
}

TEST(SurfaceNoise, GaussianNoiseOnACurvedSurfaceIsMeasured) {
  const double noise = 0.002;
  // Radius 2, step 0.3: the sagitta of a neighbour (0.3 .. 0.6 away) is 0.02 .. 0.09, 10 to 45
  // times the noise.
  const Sample s = NoisyCylinder(2.0, 6.0, 0.3, noise, 3);
  const Neighbourhoods nb = FindNeighbourhoods(s.points);
  const double estimate = EstimateSurfaceNoise(s.points, s.normals, nb.indices);
  EXPECT_GT(estimate, 1.1 * noise);
  EXPECT_LT(estimate, 1.7 * noise);
  EXPECT_GT(TangentPlaneNoise(s, nb.indices), 5 * noise);
}

TEST(SurfaceNoise, DetectorBandsComeFromTheNoiseNotTheSagitta) {
  // A noise-free coarse sphere: the distance band is the spacing floor 0.1 s (the tangent-plane
  // noise made it 3 x 0.18 = 3 spacing tenths wider on Fit4CAD PC21), and the sphere is found.
  const Sample s = Sphere(2000, 12.7);
  const Neighbourhoods nb = FindNeighbourhoods(s.points);
  const DetectionResult r = DetectPrimitives(s.points, s.normals, nb.indices, nb.spacing);
  EXPECT_LT(r.noise, 1e-6);
  EXPECT_NEAR(r.threshold, 0.1 * nb.spacing, 1e-12);
  ASSERT_EQ(r.primitives.size(), 1u);
  EXPECT_EQ(r.primitives[0].kind, NodeType::kSphere);
  EXPECT_NEAR(r.primitives[0].parameters[3], 12.7, 1e-6);
}

}  // namespace
}  // namespace implicitfit
