// BernsteinGrid::Locate at `count` random points of the grid's box (seeded) against the oracle's
// barycentric coordinates (oracle/bernstein_oracle.h) in the tetrahedron it names, whose corners
// `corners(t)` gives: every coordinate >= -1e-12 and within 1e-12 of the oracle's.
#pragma once

#include <gtest/gtest.h>

#include <array>
#include <functional>
#include <random>

#include "model/bernstein/bernstein_mesh.h"
#include "oracle/bernstein_oracle.h"

namespace testsupport {

inline void ExpectLocateMatchesOracle(
    const implicitfit::BernsteinGrid& g,
    const std::function<std::array<Eigen::Vector3d, 4>(long long)>& corners, int count,
    unsigned seed) {
  using Vec = Eigen::Vector3d;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const Vec ext = g.BoxMax() - g.BoxMin();
  for (int n = 0; n < count; ++n) {
    const Vec x = g.BoxMin() + ext.cwiseProduct(Vec(u(rng), u(rng), u(rng)));
    double tau[4];
    const long long t = g.Locate(x.data(), tau);
    const Eigen::Vector4d ref = oracle::Barycentric(corners(t), x);
    for (int i = 0; i < 4; ++i) {
      EXPECT_GE(tau[i], -1e-12);
      EXPECT_NEAR(tau[i], ref[i], 1e-12);
    }
  }
}

}  // namespace testsupport
