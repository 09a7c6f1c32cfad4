#include "model/blends/partition_sequence.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>

namespace implicitfit {
namespace {

// Half-spaces a . x <= b.
struct HalfSpace {
  Eigen::Vector3d a;
  double b;
};

// Scale of the problem: the largest separator offset (at least 1).
double SizeOf(const std::vector<SeparatorPlane>& separators) {
  double s = 1.0;
  for (const SeparatorPlane& p : separators) s = std::max(s, std::abs(p.offset));
  return s;
}

// Cell j shrunk by r, inside the box |x_k| <= L (the box is not shrunk: it only bounds the
// polytope, so that a non-empty one has a vertex).
std::vector<HalfSpace> ShrunkCell(const std::vector<SeparatorPlane>& separators, int cell, double r,
                                  double box) {
  std::vector<HalfSpace> h;
  const int m = static_cast<int>(separators.size());
  for (int i = 0; i < std::min(cell, m); ++i) {  // s_i <= -r
    const Eigen::Vector3d n = separators[i].normal.normalized();
    h.push_back({n, separators[i].offset / separators[i].normal.norm() - r});
  }
  if (cell < m) {  // s_(cell+1) >= r
    const Eigen::Vector3d n = separators[cell].normal.normalized();
    h.push_back({-n, -separators[cell].offset / separators[cell].normal.norm() - r});
  }
  for (int k = 0; k < 3; ++k) {
    h.push_back({Eigen::Vector3d::Unit(k), box});
    h.push_back({-Eigen::Vector3d::Unit(k), box});
  }
  return h;
}

// Non-empty bounded polytope <=> one of its vertices (three active planes) is feasible.
bool Feasible(const std::vector<HalfSpace>& h, double box) {
  const int n = static_cast<int>(h.size());
  const double tol = 1e-15 * box;  // rounding of a vertex of coordinates up to the box
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j)
      for (int k = j + 1; k < n; ++k) {
        Eigen::Matrix3d a;
        a << h[i].a.transpose(), h[j].a.transpose(), h[k].a.transpose();
        const double det = a.determinant();
        if (std::abs(det) < 1e-12) continue;
        const Eigen::Vector3d x = a.inverse() * Eigen::Vector3d(h[i].b, h[j].b, h[k].b);
        bool ok = true;
        for (int q = 0; q < n && ok; ++q) ok = h[q].a.dot(x) <= h[q].b + tol;
        if (ok) return true;
      }
  return false;
}

}  // namespace

bool PartitionSequenceCoreIsNonEmpty(const std::vector<SeparatorPlane>& separators, int cell,
                                     double r) {
  const double box = 1e4 * SizeOf(separators);
  return Feasible(ShrunkCell(separators, cell, r, box), box);
}

double PartitionSequenceCellWidth(const std::vector<SeparatorPlane>& separators, int cell) {
  const double box = 1e4 * SizeOf(separators);
  double hi = 1e3 * SizeOf(separators);
  if (Feasible(ShrunkCell(separators, cell, hi, box), box))
    return std::numeric_limits<double>::infinity();
  if (!Feasible(ShrunkCell(separators, cell, 0.0, box), box)) return 0.0;
  double lo = 0.0;
  for (int it = 0; it < 200 && hi - lo > 1e-10 * hi; ++it) {
    const double mid = 0.5 * (lo + hi);
    (Feasible(ShrunkCell(separators, cell, mid, box), box) ? lo : hi) = mid;
  }
  return 2.0 * lo;
}

int NarrowPartitionSequenceCell(const std::vector<SeparatorPlane>& separators, double eps,
                                double* width) {
  for (int j = 0; j <= static_cast<int>(separators.size()); ++j)
    if (!PartitionSequenceCoreIsNonEmpty(separators, j, eps)) {
      if (width) *width = PartitionSequenceCellWidth(separators, j);
      return j;
    }
  return -1;
}

double SmallestPartitionSequenceCell(const std::vector<SeparatorPlane>& separators) {
  double w = std::numeric_limits<double>::infinity();
  for (int j = 0; j <= static_cast<int>(separators.size()); ++j)
    w = std::min(w, PartitionSequenceCellWidth(separators, j));
  return w;
}

}  // namespace implicitfit
