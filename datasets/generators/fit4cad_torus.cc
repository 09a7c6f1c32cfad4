#include "datasets/generators/fit4cad_torus.h"

#include <Eigen/Geometry>
#include <cmath>
#include <stdexcept>

namespace implicitfit {

Model Fit4CadTorusFromParametric(const std::vector<double>& q) {
  if (q.size() != 18)
    throw std::invalid_argument("a Fit4CAD parametric torus has 18 numbers, got " +
                                std::to_string(q.size()));
  auto v = [&](int i) { return Eigen::Vector3d(q[3 * i], q[3 * i + 1], q[3 * i + 2]); };
  const Eigen::Vector3d a = v(0), b = v(1), c = v(2), d = v(3), e = v(4), o = v(5);
  const double major = a.norm(), minor = e.norm();
  const double tol = 1e-6 * (major + minor);
  const bool frame = major > 0 && minor > 0 && std::abs(b.norm() - major) < tol &&
                     std::abs(c.norm() - minor) < tol && std::abs(d.norm() - minor) < tol &&
                     (a / major - c / minor).norm() < 1e-6 &&
                     (b / major - d / minor).norm() < 1e-6 && std::abs(a.dot(b)) < tol * major &&
                     std::abs(e.dot(a)) < tol * major && std::abs(e.dot(b)) < tol * major;
  if (!frame)
    throw std::invalid_argument(
        "the Fit4CAD parametric torus's vectors are not R e1, R e2, r e1, r e2, r e3, centre");
  const Eigen::Vector3d axis = a.cross(b).normalized();
  Model m;
  m.SetRoot(m.AddPrimitive(NodeType::kTorus,
                           {o.x(), o.y(), o.z(), axis.x(), axis.y(), axis.z(), major, minor}));
  return m;
}

}  // namespace implicitfit
