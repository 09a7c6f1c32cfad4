#include "fit/bernstein/empty_space_sign_guard.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "model/bernstein/bernstein_patch.h"

namespace implicitfit {
namespace {

signed char SignOf(double v) { return v > 0 ? 1 : (v < 0 ? -1 : 0); }

}  // namespace

EmptySpaceSignGuard::EmptySpaceSignGuard(const BernsteinGrid& grid,
                                         const std::vector<Eigen::Vector3d>& points, double band,
                                         int samples_per_cube)
    : grid_(grid) {
  if (samples_per_cube < 1) throw std::invalid_argument("samples_per_cube must be >= 1");
  if (!(band >= 0.0 && std::isfinite(band))) throw std::invalid_argument("the band must be >= 0");
  const int reach = std::max(1, static_cast<int>(std::ceil(band / grid.cell)));
  // Bucket grid: the points of every cube (points outside the box go to the nearest cube).
  const auto cube_of = [&](const Eigen::Vector3d& x, int a) {
    const double s = std::floor((x[a] - grid.origin[a]) / grid.cell);
    return static_cast<int>(std::clamp(s, 0.0, double(grid.cells[a] - 1)));
  };
  const auto index = [&](int i, int j, int l) {
    return (1LL * l * grid.cells[1] + j) * grid.cells[0] + i;
  };
  std::vector<std::vector<int>> bucket(static_cast<size_t>(grid.NumCubes()));
  for (size_t q = 0; q < points.size(); ++q)
    bucket[index(cube_of(points[q], 0), cube_of(points[q], 1), cube_of(points[q], 2))].push_back(
        static_cast<int>(q));
  const double step = grid.cell / samples_per_cube;
  rho_ = step * std::sqrt(3.0) / 2;
  const int m[3] = {samples_per_cube * grid.cells[0], samples_per_cube * grid.cells[1],
                    samples_per_cube * grid.cells[2]};
  for (int l = 0; l <= m[2]; ++l)
    for (int j = 0; j <= m[1]; ++j)
      for (int i = 0; i <= m[0]; ++i) {
        const Eigen::Vector3d x = grid.origin + step * Eigen::Vector3d(i, j, l);
        int c[3];
        for (int a = 0; a < 3; ++a) c[a] = cube_of(x, a);
        bool near = false;
        for (int dl = -reach; dl <= reach && !near; ++dl)
          for (int dj = -reach; dj <= reach && !near; ++dj)
            for (int di = -reach; di <= reach && !near; ++di) {
              const int ci = c[0] + di, cj = c[1] + dj, cl = c[2] + dl;
              if (ci < 0 || cj < 0 || cl < 0 || ci >= grid.cells[0] || cj >= grid.cells[1] ||
                  cl >= grid.cells[2])
                continue;
              for (int q : bucket[index(ci, cj, cl)])
                if ((points[q] - x).squaredNorm() <= band * band) {
                  near = true;
                  break;
                }
            }
        if (!near) samples_.push_back(x);
      }
}

namespace {

// f(x) and its first-order distance |f| / |grad f| to the zero set.
double ValueAndDistance(const BernsteinGrid& grid, int degree, const std::vector<double>& b,
                        const Eigen::Vector3d& x, double* distance) {
  double tau[4];
  const long long t = grid.Locate(x.data(), tau);
  Eigen::Vector3d g;
  const double f =
      BernsteinPatch::Derivatives(degree, grid.TetrahedronOf(t),
                                  b.data() + t * NumBernsteinControlPoints(degree), x.data(), &g);
  const double gn = g.norm();
  *distance = gn > 0 ? std::abs(f) / gn : std::numeric_limits<double>::infinity();
  return f;
}

}  // namespace

void EmptySpaceSignGuard::Record(int degree, const std::vector<double>& control_points) {
  degree_ = degree;
  signs_.resize(samples_.size());
  clear_.resize(samples_.size());
  for (size_t s = 0; s < samples_.size(); ++s) {
    double e;
    signs_[s] = SignOf(ValueAndDistance(grid_, degree, control_points, samples_[s], &e));
    clear_[s] = e > 2 * rho_;
  }
}

long long EmptySpaceSignGuard::Changes(int degree,
                                       const std::vector<double>& control_points) const {
  return static_cast<long long>(Tripped(degree, control_points).size());
}

std::vector<EmptySpaceSignGuard::Trip> EmptySpaceSignGuard::Tripped(
    int degree, const std::vector<double>& control_points) const {
  if (signs_.size() != samples_.size() || degree != degree_)
    throw std::logic_error("EmptySpaceSignGuard::Changes before Record (or another degree)");
  std::vector<Trip> tripped;
  for (size_t s = 0; s < samples_.size(); ++s) {
    if (!clear_[s]) continue;
    double e;
    const double f = ValueAndDistance(grid_, degree, control_points, samples_[s], &e);
    const bool sign_changed = SignOf(f) != signs_[s];
    if (sign_changed || e <= rho_) tripped.push_back({samples_[s], sign_changed});
  }
  return tripped;
}

std::vector<Eigen::Vector3d> EmptySpaceSignGuard::WatchedNear(
    const std::vector<Eigen::Vector3d>& centres, double radius) const {
  if (clear_.size() != samples_.size())
    throw std::logic_error("EmptySpaceSignGuard::WatchedNear before Record");
  std::vector<Eigen::Vector3d> near;
  for (size_t s = 0; s < samples_.size(); ++s) {
    if (!clear_[s]) continue;
    for (const Eigen::Vector3d& c : centres)
      if ((samples_[s] - c).lpNorm<Eigen::Infinity>() <= radius) {
        near.push_back(samples_[s]);
        break;
      }
  }
  return near;
}

}  // namespace implicitfit
