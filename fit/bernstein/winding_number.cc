#include "fit/bernstein/winding_number.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>

#include "fit/bernstein/point_hash_grid.h"

namespace implicitfit {
namespace {

using Vec = Eigen::Vector3d;

// The k nearest neighbours of point i that face the same way (n_i . n_j > 0; itself excluded),
// nearest first, as (squared distance, index) (fewer than k when the cloud has fewer).
std::vector<std::pair<double, int>> NearestSameFacing(const PointHashGrid& grid,
                                                      const std::vector<Vec>& points,
                                                      const std::vector<Vec>& normals, size_t i,
                                                      int k) {
  return grid.Nearest(points[i], k, [&](int j) {
    return static_cast<size_t>(j) != i && normals[i].dot(normals[j]) > 0;
  });
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
  const PointHashGrid grid(points, std::max(spacing, 1e-6 * diagonal));
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
