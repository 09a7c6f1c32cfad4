#include "fit/fillet_separators.h"

#include <Eigen/Geometry>
#include <algorithm>

namespace implicitfit {

using Vec = Eigen::Vector3d;

Model CylinderLiteral::ToModel(const std::string& name) const {
  Model m;
  m.SetRoot(m.AddPrimitive(NodeType::kCylinder,
                           {point.x(), point.y(), point.z(), axis.x(), axis.y(), axis.z(), radius},
                           name));
  m.mutable_nodes()[m.root()].fixed = {"point", "axis", "radius"};
  return m;
}

bool FilletBoundsOf(const Model& torus, const std::vector<Vec>& points, double margin,
                    FilletBounds* bounds) {
  if (torus.nodes().size() != 1 || torus.nodes()[torus.root()].type != NodeType::kTorus ||
      points.size() < 3)
    return false;
  const double* p = torus.parameters().data() + torus.nodes()[torus.root()].first_parameter;
  const Vec c(p[0], p[1], p[2]);
  const Vec u = Vec(p[3], p[4], p[5]).normalized();
  double h_lo = 1e300, h_hi = -1e300, rho_lo = 1e300, rho_hi = 0;
  for (const Vec& x : points) {
    const double h = u.dot(x - c);
    const double rho = (x - c).cross(u).norm();
    h_lo = std::min(h_lo, h);
    h_hi = std::max(h_hi, h);
    rho_lo = std::min(rho_lo, rho);
    rho_hi = std::max(rho_hi, rho);
  }
  // low: material where -u . x < -(u . c + h_lo - margin); high: u . x < u . c + h_hi + margin.
  bounds->low = {-u, -(u.dot(c) + h_lo - margin)};
  bounds->high = {u, u.dot(c) + h_hi + margin};
  bounds->inner = {c, u, std::max(rho_lo - margin, 0.0)};
  bounds->outer = {c, u, rho_hi + margin};
  return true;
}

}  // namespace implicitfit
