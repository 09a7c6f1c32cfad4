// n points spread evenly over the unit sphere (Fibonacci lattice: heights z = 1 - (2i + 1) / n,
// longitudes advancing by the golden angle); each point is its own outward normal.
#pragma once

#include <Eigen/Core>
#include <cmath>
#include <vector>

namespace testsupport {

inline std::vector<Eigen::Vector3d> FibonacciSphere(int n) {
  std::vector<Eigen::Vector3d> p;
  const double golden = M_PI * (3.0 - std::sqrt(5.0));
  for (int i = 0; i < n; ++i) {
    const double z = 1.0 - 2.0 * (i + 0.5) / n, r = std::sqrt(1.0 - z * z);
    p.emplace_back(r * std::cos(golden * i), r * std::sin(golden * i), z);
  }
  return p;
}

}  // namespace testsupport
