#include "fit/bernstein/far_field_rows.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace implicitfit {

using Vec = Eigen::Vector3d;

std::vector<FarFieldRow> FarFieldRows(const BernsteinGrid& grid, const std::vector<Vec>& points,
                                      const std::vector<Vec>& normals, double band,
                                      double beside_cos, double ramp, double ramp_power,
                                      const WindingNumber* winding) {
  std::vector<FarFieldRow> rows;
  // The lattice: spacing half a leaf's edge in every leaf (for a uniform grid h/2 everywhere),
  // in units of h / 2^(max_level + 1), each point once, in the order i, j, l (outer to inner).
  const int top = grid.MaxLevel();
  const double step = std::ldexp(grid.cell, -(top + 1));
  const long long m[3] = {(2LL * grid.cells[0]) << top, (2LL * grid.cells[1]) << top,
                          (2LL * grid.cells[2]) << top};
  std::vector<std::array<long long, 3>> lattice;
  for (long long q = 0; q < grid.NumLeaves(); ++q) {
    const std::array<int, 4> leaf = grid.Leaf(q);
    // Half the leaf's edge in lattice units (Leaf() gives the corner in units of the leaf's edge).
    const long long stride = 1LL << (top - leaf[0]);
    for (int a = 0; a <= 2; ++a)
      for (int b = 0; b <= 2; ++b)
        for (int c = 0; c <= 2; ++c)
          lattice.push_back({stride * (2LL * leaf[1] + a), stride * (2LL * leaf[2] + b),
                             stride * (2LL * leaf[3] + c)});
  }
  std::sort(lattice.begin(), lattice.end());
  lattice.erase(std::unique(lattice.begin(), lattice.end()), lattice.end());
  for (const std::array<long long, 3>& ijl : lattice) {
    const long long i = ijl[0], j = ijl[1], l = ijl[2];
    const Vec c = grid.origin + step * Vec(double(i), double(j), double(l));
    size_t best = 0;
    double best_d2 = std::numeric_limits<double>::infinity();
    for (size_t q = 0; q < points.size(); ++q) {
      const double d2 = (points[q] - c).squaredNorm();
      if (d2 < best_d2) best_d2 = d2, best = q;
    }
    if (best_d2 <= band * band) continue;
    const bool on_box = i == 0 || j == 0 || l == 0 || i == m[0] || j == m[1] || l == m[2];
    const double hoppe = (c - points[best]).dot(normals[best]);
    const bool beside = std::abs(hoppe) < beside_cos * std::sqrt(best_d2);
    const double distance = std::sqrt(best_d2);
    const double weight =
        ramp > 0 && !on_box ? std::min(1.0, std::pow(distance / (ramp * grid.cell), ramp_power))
                            : 1.0;
    double target = on_box || beside ? distance : hoppe;
    if (winding && !on_box) {
      Vec grad_w;
      const double w = winding->Evaluate(c, &grad_w);
      const bool inside = w > 0.5;
      const bool agrees = !beside && (hoppe < 0) == inside;
      const double magnitude = std::min(agrees ? std::abs(hoppe) : distance,
                                        std::abs(w - 0.5) / std::max(grad_w.norm(), 1e-300));
      target = inside ? -magnitude : magnitude;
    }
    rows.push_back({c, target, on_box, weight});
  }
  return rows;
}

long long FarFieldSignErrors(const BernsteinGrid& grid, int k, const std::vector<double>& b,
                             const std::vector<FarFieldRow>& rows, bool box_only) {
  const long long n = NumBernsteinControlPoints(k);
  long long errors = 0;
  for (const FarFieldRow& r : rows) {
    if (box_only && !r.on_box) continue;
    double tau[4];
    const long long t = grid.Locate(r.x.data(), tau);
    errors += BernsteinPatch::EvaluateBarycentric(k, b.data() + t * n, tau) * r.target <= 0;
  }
  return errors;
}

}  // namespace implicitfit
