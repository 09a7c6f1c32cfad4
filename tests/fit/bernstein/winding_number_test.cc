// The generalised winding number of oriented point clouds (fit/bernstein/winding_number.h) against
// closed forms: ~1 inside and ~0 outside a sampled closed sphere, and on the axis of an open
// hemisphere (unit radius, the z >= 0 half) w(0, 0, z) = 1/2 + z / (2 sqrt(1 + z^2)) for |z| < 1:
// the hemisphere and the unit disk at z = 0 (normal -z) bound the half ball, so w_hemisphere = [x
// in the half ball] - w_disk, and the disk subtends 2 pi (1 - |z| / sqrt(1 + z^2)) at (0, 0, z). At
// z = 0 this is 1/2 exactly: the level 1/2 spans the rim (the flat cap). The point areas against
// the sphere's area 4 pi and a two-density plane.
#include "fit/bernstein/winding_number.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numeric>
#include <random>

#include "support/fibonacci_sphere.h"

namespace implicitfit {
namespace {

using Vec = Eigen::Vector3d;
using testsupport::FibonacciSphere;  // normals = points

TEST(PointAreas, SumToTheSphereArea) {
  const std::vector<Vec> p = FibonacciSphere(4000);
  const std::vector<double> a = PointAreas(p, p);
  const double total = std::accumulate(a.begin(), a.end(), 0.0);
  EXPECT_NEAR(total, 4 * M_PI, 0.05 * 4 * M_PI);
}

TEST(PointAreas, FollowTheLocalDensity) {
  // The unit square at z = 0 sampled at 40 x 40, the square next to it at 80 x 80 (4x denser):
  // interior points stand for 1/1600 and 1/6400.
  std::vector<Vec> p;
  for (int i = 0; i < 40; ++i)
    for (int j = 0; j < 40; ++j) p.emplace_back((i + 0.5) / 40, (j + 0.5) / 40, 0);
  for (int i = 0; i < 80; ++i)
    for (int j = 0; j < 80; ++j) p.emplace_back(1 + (i + 0.5) / 80, (j + 0.5) / 80, 0);
  const std::vector<double> a = PointAreas(p, std::vector<Vec>(p.size(), Vec::UnitZ()));
  // Away from the borders (where a disk of radius r is cut) the estimate is within 15%.
  for (size_t i = 0; i < p.size(); ++i) {
    const Vec& q = p[i];
    if (std::abs(q.x() - 0.5) > 0.3 || std::abs(q.y() - 0.5) > 0.3) continue;
    EXPECT_NEAR(a[i], 1.0 / 1600, 0.15 / 1600) << q.transpose();
  }
  for (size_t i = 0; i < p.size(); ++i) {
    const Vec& q = p[i];
    if (std::abs(q.x() - 1.5) > 0.3 || std::abs(q.y() - 0.5) > 0.3) continue;
    EXPECT_NEAR(a[i], 1.0 / 6400, 0.15 / 6400) << q.transpose();
  }
}

TEST(WindingNumber, InsideAndOutsideAClosedSphere) {
  const std::vector<Vec> p = FibonacciSphere(4000);
  const WindingNumber w(p, p);
  for (const Vec& x : {Vec(0, 0, 0), Vec(0.5, 0.2, -0.1), Vec(0, 0, 0.85), Vec(-0.6, 0.6, 0)})
    EXPECT_NEAR(w(x), 1.0, 0.03) << x.transpose();
  for (const Vec& x : {Vec(2, 0, 0), Vec(0, 0, -1.2), Vec(1.5, 1.5, 1.5), Vec(0.8, 0.8, 0)})
    EXPECT_NEAR(w(x), 0.0, 0.03) << x.transpose();
}

TEST(WindingNumber, OpenHemisphereAxisClosedForm) {
  std::vector<Vec> p;
  for (const Vec& q : FibonacciSphere(8000))
    if (q.z() >= 0) p.push_back(q);
  const WindingNumber w(p, p);
  for (double z : {-0.6, -0.3, 0.0, 0.3, 0.6}) {
    const double expected = 0.5 + z / (2 * std::sqrt(1 + z * z));
    EXPECT_NEAR(w(Vec(0, 0, z)), expected, 0.02) << "z " << z;
  }
  // Off the axis, on the disk spanning the rim: 1/2 as well.
  EXPECT_NEAR(w(Vec(0.5, 0.3, 0)), 0.5, 0.02);
}

}  // namespace
}  // namespace implicitfit
