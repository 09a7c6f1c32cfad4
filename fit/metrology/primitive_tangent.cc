#include "fit/metrology/primitive_tangent.h"

#include <Eigen/Geometry>
#include <cmath>

#include "fit/primitive/fittable_primitives.h"
#include "model/primitives/primitive_kinds.h"

namespace implicitfit {
namespace {

// Two orthonormal vectors orthogonal to the unit vector u.
void Orthonormal(const Eigen::Vector3d& u, Eigen::Vector3d* a, Eigen::Vector3d* b) {
  *a = u.unitOrthogonal();
  *b = u.cross(*a);
}

}  // namespace

int FreeParameterCount(NodeType kind) {
  if (!FindFittablePrimitive(kind)) return 0;
  int k = 0;
  for (const ParameterField& f : ParameterFieldsOf(kind)) k += DegreesOfFreedom(f);
  return k;
}

Eigen::MatrixXd TangentBasis(NodeType kind, const std::vector<double>& p) {
  const int P = static_cast<int>(p.size());
  Eigen::MatrixXd B = Eigen::MatrixXd::Zero(P, FreeParameterCount(kind));
  const std::vector<ParameterField>& fields = ParameterFieldsOf(kind);
  // The two unit vectors orthogonal to the kind's direction field (axis, normal).
  Eigen::Vector3d a = Eigen::Vector3d::Zero(), b = Eigen::Vector3d::Zero();
  int dir = 0;
  if (FindFieldWithRole(fields, FieldRole::kDirection, &dir))
    Orthonormal(Eigen::Vector3d(p[dir], p[dir + 1], p[dir + 2]).normalized(), &a, &b);
  int row = 0, col = 0;
  for (const ParameterField& f : fields) {
    const int dof = DegreesOfFreedom(f);
    if (f.role == FieldRole::kDirection || f.role == FieldRole::kAxisPoint) {
      // A direction moves in its tangent plane, an axis point orthogonally to the axis.
      B.block<3, 1>(row, col) = a;
      B.block<3, 1>(row, col + 1) = b;
    } else if (dof == f.size) {
      for (int j = 0; j < f.size; ++j) B(row + j, col + j) = 1.0;
    }  // a rotation (3 of 4 numbers) is not fitted here: its columns stay 0
    row += f.size;
    col += dof;
  }
  return B;
}

void Retract(NodeType kind, const Eigen::MatrixXd& basis, const Eigen::VectorXd& delta,
             std::vector<double>* params) {
  const Eigen::VectorXd step = basis * delta;
  for (size_t i = 0; i < params->size(); ++i) (*params)[i] += step[i];
  int k = 0;
  for (const ParameterField& f : ParameterFieldsOf(kind)) {
    if (f.role == FieldRole::kDirection)
      Eigen::Map<Eigen::Vector3d>(params->data() + k).normalize();
    k += f.size;
  }
}

double PrimitiveSignedDistance(NodeType kind, const double* p, const double* x, double* dp) {
  if (!FindFittablePrimitive(kind)) return NAN;
  return VisitFittablePrimitive(
      kind, [&](auto e) { return PrimitiveDistance<decltype(e)>(p)(x, dp, nullptr); });
}

void TranslatePrimitive(NodeType kind, const Eigen::Vector3d& shift, std::vector<double>* p) {
  const std::vector<ParameterField>& fields = ParameterFieldsOf(kind);
  int k = 0;
  for (const ParameterField& f : fields) {
    if (f.role == FieldRole::kPosition || f.role == FieldRole::kAxisPoint)
      for (int j = 0; j < 3; ++j) (*p)[k + j] += shift[j];
    if (f.role == FieldRole::kPlaneOffset) {
      int dir = 0;
      FindFieldWithRole(fields, FieldRole::kDirection, &dir);
      const Eigen::Vector3d n((*p)[dir], (*p)[dir + 1], (*p)[dir + 2]);
      (*p)[k] += n.dot(shift);  // n . (x + shift) = d + n . shift
    }
    k += f.size;
  }
}

}  // namespace implicitfit
