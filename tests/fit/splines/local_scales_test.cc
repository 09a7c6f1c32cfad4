// The freeform stage's local scales (fit/splines/local_scales.h) against closed forms: on a plane
// with normal noise sigma the part's sigma_P is sigma (within 10%: 4 000 points), tau_P = 3 sigma_P
// and the normal band is the detection's (exact normals: a_i = 0); a noise growing along x gives
// each half its own sigma; uniform random points with random normals fill a volume.
#include "fit/splines/local_scales.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <numeric>
#include <random>

#include "datasets/normals/neighbourhoods.h"

namespace implicitfit {
namespace {

using Vec = Eigen::Vector3d;

TEST(LocalScales, PlaneNoiseIsRecovered) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::normal_distribution<double> unit(0.0, 1.0);
  std::vector<Vec> points, normals;
  const double sigma_lo = 0.002, sigma_hi = 0.006;  // x < 0.5, x >= 0.5
  for (int i = 0; i < 8000; ++i) {
    const double x = u(rng);
    points.emplace_back(x, u(rng), (x < 0.5 ? sigma_lo : sigma_hi) * unit(rng));
    normals.emplace_back(0, 0, 1);
  }
  const Neighbourhoods nb = FindNeighbourhoods(points);
  const LocalScaleFigures f = ComputeLocalScaleFigures(points, normals, nb.indices, 20.0);
  std::vector<int> lo, hi;  // away from the step, so neighbourhoods do not straddle it
  for (int i = 0; i < static_cast<int>(points.size()); ++i) {
    if (points[i].x() < 0.45) lo.push_back(i);
    if (points[i].x() > 0.55) hi.push_back(i);
  }
  const DetectionBands bands{0.001, 0.003, 20.0, nb.spacing};
  const PartScales a = ScalesOfPart(f, lo, bands), b = ScalesOfPart(f, hi, bands);
  EXPECT_NEAR(a.noise, sigma_lo, 0.1 * sigma_lo);
  EXPECT_NEAR(b.noise, sigma_hi, 0.1 * sigma_hi);
  EXPECT_DOUBLE_EQ(a.threshold, std::max(3 * a.noise, 0.1 * nb.spacing));
  EXPECT_NEAR(a.cos_normal_angle, std::cos(20.0 * M_PI / 180.0), 1e-12);
  EXPECT_FALSE(a.volume);
  EXPECT_FALSE(b.volume);
  // Without a spacing a part is never held tighter than the detection.
  const PartScales c = ScalesOfPart(f, lo, DetectionBands{0.004, 0.012, 20.0, 0.0});
  EXPECT_DOUBLE_EQ(c.noise, 0.004);
  EXPECT_DOUBLE_EQ(c.threshold, 0.012);
}

TEST(LocalScales, RandomPointsFillAVolume) {
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<Vec> points, normals;
  for (int i = 0; i < 3000; ++i) {
    points.emplace_back(u(rng), u(rng), u(rng));
    normals.push_back(Vec(u(rng), u(rng), u(rng)).normalized());
  }
  const Neighbourhoods nb = FindNeighbourhoods(points);
  const LocalScaleFigures f = ComputeLocalScaleFigures(points, normals, nb.indices, 20.0);
  std::vector<int> all(points.size());
  std::iota(all.begin(), all.end(), 0);
  EXPECT_TRUE(ScalesOfPart(f, all, DetectionBands{0.01, 0.03, 20.0, nb.spacing}).volume);
}

}  // namespace
}  // namespace implicitfit
