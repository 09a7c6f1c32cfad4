#include "fit/bernstein/winding_number.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <unordered_map>
#include <utility>

namespace implicitfit {
namespace {

using Vec = Eigen::Vector3d;

// Points hashed into cubes of edge `cell`; queries visit the rings of cubes around a point.
class HashGrid {
 public:
  HashGrid(const std::vector<Vec>& points, double cell) : points_(points), cell_(cell) {
    lo_ = points[0];
    for (const Vec& p : points) lo_ = lo_.cwiseMin(p);
    for (size_t i = 0; i < points.size(); ++i)
      cells_[Key(CellOf(points[i]))].push_back(static_cast<int>(i));
  }
  // fn(j, squared distance) for every point j within the cubes of Chebyshev ring <= rings.
  template <class Fn>
  void ForRings(const Vec& x, int first_ring, int last_ring, Fn&& fn) const {
    const Eigen::Vector3i c = CellOf(x);
    for (int dx = -last_ring; dx <= last_ring; ++dx)
      for (int dy = -last_ring; dy <= last_ring; ++dy)
        for (int dz = -last_ring; dz <= last_ring; ++dz) {
          if (std::max({std::abs(dx), std::abs(dy), std::abs(dz)}) < first_ring) continue;
          const Eigen::Vector3i n = c + Eigen::Vector3i(dx, dy, dz);
          if (n.minCoeff() < 0) continue;
          const auto it = cells_.find(Key(n));
          if (it == cells_.end()) continue;
          for (int j : it->second) fn(j, (points_[j] - x).squaredNorm());
        }
  }
  // Rings of cubes that hold every point within distance r of a point.
  int RingsFor(double r) const { return static_cast<int>(std::ceil(r / cell_)); }
  double cell() const { return cell_; }

 private:
  Eigen::Vector3i CellOf(const Vec& p) const {
    return ((p - lo_) / cell_).array().floor().cast<int>();
  }
  // Cells are non-negative and below 2^21 per axis (cell >= diagonal / 10^6).
  static std::uint64_t Key(const Eigen::Vector3i& c) {
    return (static_cast<std::uint64_t>(c.x()) << 42) | (static_cast<std::uint64_t>(c.y()) << 21) |
           static_cast<std::uint64_t>(c.z());
  }
  const std::vector<Vec>& points_;
  double cell_;
  Vec lo_;
  std::unordered_map<std::uint64_t, std::vector<int>> cells_;
};

// The k nearest neighbours of point i that face the same way (n_i . n_j > 0; itself excluded),
// nearest first, as (squared distance, index): rings of cubes grow until k are found and the
// next ring is farther than the k-th (fewer than k when the cloud has fewer).
std::vector<std::pair<double, int>> NearestSameFacing(const HashGrid& grid,
                                                      const std::vector<Vec>& points,
                                                      const std::vector<Vec>& normals, size_t i,
                                                      int k) {
  std::vector<std::pair<double, int>> found;
  size_t seen = 1;  // points visited, itself included
  for (int ring = 0; seen < points.size(); ++ring) {
    grid.ForRings(points[i], ring, ring, [&](int j, double q) {
      if (static_cast<size_t>(j) == i) return;
      ++seen;
      if (normals[i].dot(normals[j]) > 0) found.emplace_back(q, j);
    });
    if (static_cast<int>(found.size()) >= k) {
      std::nth_element(found.begin(), found.begin() + (k - 1), found.end());
      const double reach = ring * grid.cell();  // every point of later rings is farther
      if (found[k - 1].first <= reach * reach) break;
    }
  }
  std::sort(found.begin(), found.end());
  if (static_cast<int>(found.size()) > k) found.resize(k);
  return found;
}

// Area of the convex polygon (counter-clockwise or not).
double PolygonArea(const std::vector<Eigen::Vector2d>& poly) {
  double twice = 0;
  for (size_t a = 0; a < poly.size(); ++a) {
    const Eigen::Vector2d& p = poly[a];
    const Eigen::Vector2d& q = poly[(a + 1) % poly.size()];
    twice += p.x() * q.y() - q.x() * p.y();
  }
  return 0.5 * std::abs(twice);
}

// The part of the convex polygon where e . x <= c (Sutherland-Hodgman, one half-plane).
std::vector<Eigen::Vector2d> ClipHalfPlane(const std::vector<Eigen::Vector2d>& poly,
                                           const Eigen::Vector2d& e, double c) {
  std::vector<Eigen::Vector2d> out;
  for (size_t a = 0; a < poly.size(); ++a) {
    const Eigen::Vector2d& p = poly[a];
    const Eigen::Vector2d& q = poly[(a + 1) % poly.size()];
    const double fp = e.dot(p) - c, fq = e.dot(q) - c;
    if (fp <= 0) out.push_back(p);
    if ((fp < 0 && fq > 0) || (fp > 0 && fq < 0)) out.push_back(p + fp / (fp - fq) * (q - p));
  }
  return out;
}

}  // namespace

std::vector<double> PointAreas(const std::vector<Vec>& points, const std::vector<Vec>& normals) {
  if (normals.size() != points.size())
    throw std::invalid_argument("PointAreas: one normal per point is needed");
  if (points.empty()) return {};
  Vec lo = points[0], hi = points[0];
  for (const Vec& p : points) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  const double diagonal = (hi - lo).norm();
  if (points.size() == 1 || !(diagonal > 0) || !std::isfinite(diagonal))
    throw std::invalid_argument("PointAreas: the points must span a finite, non-empty box");
  const double spacing = diagonal / std::sqrt(static_cast<double>(points.size()));
  const HashGrid grid(points, std::max(spacing, 1e-6 * diagonal));
  constexpr int kNeighbours = 16, kClip = 8;  // see the header
  constexpr int kSides = 32;
  std::vector<double> areas(points.size());
  for (size_t i = 0; i < points.size(); ++i) {
    const std::vector<std::pair<double, int>> near =
        NearestSameFacing(grid, points, normals, i, kNeighbours);
    const double radius =
        near.empty() ? spacing : std::sqrt(near[std::min<size_t>(kClip, near.size()) - 1].first);
    // Tangent-plane basis (u, v) of n_i.
    const Vec& n = normals[i];
    const Vec u =
        (std::abs(n.x()) < 0.9 ? n.cross(Vec::UnitX()) : n.cross(Vec::UnitY())).normalized();
    const Vec v = n.cross(u);
    std::vector<Eigen::Vector2d> cell(kSides);
    for (int a = 0; a < kSides; ++a)
      cell[a] = radius *
                Eigen::Vector2d(std::cos(2 * M_PI * a / kSides), std::sin(2 * M_PI * a / kSides));
    double nearest = radius;  // the nearest neighbour's distance in the tangent plane
    for (const auto& [d2, j] : near) {
      const Vec offset = points[j] - points[i];
      const Eigen::Vector2d e(offset.dot(u), offset.dot(v));
      if (e.squaredNorm() <= 1e-24 * diagonal * diagonal) continue;  // a duplicate
      nearest = std::min(nearest, e.norm());
      cell = ClipHalfPlane(cell, e, 0.5 * e.squaredNorm());
      if (cell.size() < 3) break;
    }
    // A point on the rim of an open scan: its cell still reaches the clipping circle on the
    // open side. Close it as if a neighbour sat at the nearest neighbour's distance there (the
    // last sample stands for half a spacing beyond itself, as samples do inside).
    Eigen::Vector2d open = Eigen::Vector2d::Zero();
    for (const Eigen::Vector2d& x : cell)
      if (x.norm() >= (1 - 1e-9) * radius) open += x;
    if (cell.size() >= 3 && open.norm() > 1e-12 * radius)
      cell = ClipHalfPlane(cell, open.normalized(), 0.5 * nearest);
    areas[i] = cell.size() < 3 ? 0.0 : PolygonArea(cell);
  }
  return areas;
}

WindingNumber::WindingNumber(const std::vector<Vec>& points, const std::vector<Vec>& normals)
    : points_(points) {
  if (normals.size() != points.size())
    throw std::invalid_argument("WindingNumber: one normal per point is needed");
  const std::vector<double> areas = PointAreas(points, normals);
  weighted_normals_.resize(points.size());
  for (size_t i = 0; i < points.size(); ++i)
    weighted_normals_[i] = areas[i] / (4 * M_PI) * normals[i];
}

double WindingNumber::Evaluate(const Vec& x, Vec* gradient) const {
  double w = 0;
  Vec g = Vec::Zero();
  for (size_t i = 0; i < points_.size(); ++i) {
    const Vec d = points_[i] - x;
    const double r2 = d.squaredNorm();
    if (r2 == 0) continue;  // on a sample: its own disk contributes its principal value, 0
    const double r3 = r2 * std::sqrt(r2), nd = d.dot(weighted_normals_[i]);
    w += nd / r3;
    if (gradient) g += (3 * nd / r2 * d - weighted_normals_[i]) / r3;
  }
  if (gradient) *gradient = g;
  return w;
}

}  // namespace implicitfit
