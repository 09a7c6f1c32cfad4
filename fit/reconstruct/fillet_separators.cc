#include "fit/reconstruct/fillet_separators.h"

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

namespace {

bool IsOneTorus(const Model& torus) {
  return torus.nodes().size() == 1 && torus.nodes()[torus.root()].type == NodeType::kTorus;
}

// (h, rho) of the box of revolution from the points' (h, rho) pairs.
void SetBounds(const Vec& c, const Vec& u, double h_lo, double h_hi, double rho_lo, double rho_hi,
               double margin, FilletBounds* bounds) {
  // low: material where -u . x < -(u . c + h_lo - margin); high: u . x < u . c + h_hi + margin.
  bounds->low = {-u, -(u.dot(c) + h_lo - margin)};
  bounds->high = {u, u.dot(c) + h_hi + margin};
  bounds->inner = {c, u, std::max(rho_lo - margin, 0.0)};
  bounds->outer = {c, u, rho_hi + margin};
}

}  // namespace

bool FilletBoundsOf(const Model& torus, const std::vector<Vec>& points, double margin,
                    FilletBounds* bounds) {
  if (!IsOneTorus(torus) || points.size() < 3) return false;
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
  SetBounds(c, u, h_lo, h_hi, rho_lo, rho_hi, margin, bounds);
  return true;
}

bool FilletBoundsOf(const Model& torus, const std::vector<Vec>& points,
                    const std::vector<Vec>& normals, double margin, FilletBounds* bounds) {
  if (!IsOneTorus(torus) || points.size() < 3 || normals.size() != points.size()) return false;
  const double* p = torus.parameters().data() + torus.nodes()[torus.root()].first_parameter;
  const Vec c(p[0], p[1], p[2]);
  const Vec u = Vec(p[3], p[4], p[5]).normalized();
  const double major = p[6], minor = p[7];
  double h_lo = 1e300, h_hi = -1e300, rho_lo = 1e300, rho_hi = 0;
  size_t used = 0;
  for (size_t i = 0; i < points.size(); ++i) {
    const Vec d = points[i] - c;
    const Vec radial = d - u.dot(d) * u;
    if (!(radial.norm() > 0)) continue;
    const Vec e = radial.normalized();
    // The normal signed away from the centre circle, in the meridian plane (e, u).
    const Vec away = d - major * e;
    const double s = normals[i].dot(away) < 0 ? -1.0 : 1.0;
    const Eigen::Vector2d m(s * normals[i].dot(e), s * normals[i].dot(u));
    if (!(m.norm() > 0.5)) continue;  // the normal leaves the meridian plane: unreliable
    const Eigen::Vector2d w = m.normalized();
    const double rho = major + minor * w.x(), h = minor * w.y();  // the foot on the tube
    h_lo = std::min(h_lo, h);
    h_hi = std::max(h_hi, h);
    rho_lo = std::min(rho_lo, rho);
    rho_hi = std::max(rho_hi, rho);
    ++used;
  }
  if (used < 3) return false;
  SetBounds(c, u, h_lo, h_hi, rho_lo, rho_hi, margin, bounds);
  return true;
}
}  // namespace implicitfit
