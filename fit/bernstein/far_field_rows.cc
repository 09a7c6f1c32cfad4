#include "fit/bernstein/far_field_rows.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace implicitfit {

using Vec = Eigen::Vector3d;

std::vector<FarFieldRow> FarFieldRows(const BernsteinGrid& grid, const std::vector<Vec>& points,
                                      const std::vector<Vec>& normals, double band,
                                      double beside_cos, double ramp, double ramp_power,
                                      const WindingNumber* winding) {
  std::vector<FarFieldRow> rows;
  const int per = 2;  // samples per cube edge
  const double step = grid.cell / per;
  const int m[3] = {per * grid.cells[0], per * grid.cells[1], per * grid.cells[2]};
  for (int i = 0; i <= m[0]; ++i)
    for (int j = 0; j <= m[1]; ++j)
      for (int l = 0; l <= m[2]; ++l) {
        const Vec c = grid.origin + step * Vec(i, j, l);
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
