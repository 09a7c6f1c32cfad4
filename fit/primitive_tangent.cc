#include "fit/primitive_tangent.h"

#include <Eigen/Geometry>
#include <cmath>

#include "fit/primitive_jacobians.h"

namespace implicitfit {
namespace {

// Two orthonormal vectors orthogonal to the unit vector u.
void Orthonormal(const Eigen::Vector3d& u, Eigen::Vector3d* a, Eigen::Vector3d* b) {
  *a = u.unitOrthogonal();
  *b = u.cross(*a);
}

}  // namespace

int FreeParameterCount(NodeType kind) {
  switch (kind) {
    case NodeType::kPlane:
      return 3;
    case NodeType::kSphere:
      return 4;
    case NodeType::kCylinder:
      return 5;
    case NodeType::kCone:
      return 6;
    case NodeType::kTorus:
      return 7;
    default:
      return 0;
  }
}

Eigen::MatrixXd TangentBasis(NodeType kind, const std::vector<double>& p) {
  const int P = static_cast<int>(p.size());
  Eigen::MatrixXd B = Eigen::MatrixXd::Zero(P, FreeParameterCount(kind));
  auto put_direction = [&](int row, int col) {
    const Eigen::Vector3d u = Eigen::Vector3d(p[row], p[row + 1], p[row + 2]).normalized();
    Eigen::Vector3d a, b;
    Orthonormal(u, &a, &b);
    B.block<3, 1>(row, col) = a;
    B.block<3, 1>(row, col + 1) = b;
  };
  switch (kind) {
    case NodeType::kPlane:  // normal 3, offset
      put_direction(0, 0);
      B(3, 2) = 1;
      break;
    case NodeType::kSphere:  // center 3, radius
      B.setIdentity();
      break;
    case NodeType::kCylinder:  // point 3 (orthogonal to the axis only), axis 3, radius
      put_direction(3, 0);
      B.block<3, 2>(0, 2) = B.block<3, 2>(3, 0);
      B(6, 4) = 1;
      break;
    case NodeType::kCone:  // apex 3, axis 3, half angle
      B.block<3, 3>(0, 0).setIdentity();
      put_direction(3, 3);
      B(6, 5) = 1;
      break;
    case NodeType::kTorus:  // center 3, axis 3, major radius, minor radius
      B.block<3, 3>(0, 0).setIdentity();
      put_direction(3, 3);
      B(6, 5) = 1;
      B(7, 6) = 1;
      break;
    default:
      break;
  }
  return B;
}

void Retract(NodeType kind, const Eigen::MatrixXd& basis, const Eigen::VectorXd& delta,
             std::vector<double>* params) {
  const Eigen::VectorXd step = basis * delta;
  for (size_t i = 0; i < params->size(); ++i) (*params)[i] += step[i];
  const int dir = kind == NodeType::kPlane ? 0 : kind == NodeType::kSphere ? -1 : 3;
  if (dir >= 0) {
    Eigen::Map<Eigen::Vector3d> u(params->data() + dir);
    u.normalize();
  }
}

double PrimitiveSignedDistance(NodeType kind, const double* p, const double* x, double* dp) {
  switch (kind) {
    case NodeType::kPlane:
      return PrimitiveDistance<PlaneEvaluator>(p)(x, dp, nullptr);
    case NodeType::kSphere:
      return PrimitiveDistance<SphereEvaluator>(p)(x, dp, nullptr);
    case NodeType::kCylinder:
      return PrimitiveDistance<CylinderEvaluator>(p)(x, dp, nullptr);
    case NodeType::kCone:
      return PrimitiveDistance<ConeEvaluator>(p)(x, dp, nullptr);
    case NodeType::kTorus:
      return PrimitiveDistance<TorusEvaluator>(p)(x, dp, nullptr);
    default:
      return NAN;
  }
}

}  // namespace implicitfit

namespace implicitfit {

void TranslatePrimitive(NodeType kind, const Eigen::Vector3d& shift, std::vector<double>* p) {
  if (kind == NodeType::kPlane) {
    const Eigen::Vector3d n((*p)[0], (*p)[1], (*p)[2]);
    (*p)[3] += n.dot(shift) / n.norm();
    return;
  }
  for (int j = 0; j < 3; ++j) (*p)[j] += shift[j];  // centre, axis point or apex come first
}

}  // namespace implicitfit
