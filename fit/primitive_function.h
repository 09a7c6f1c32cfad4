// f(x) and grad_x f(x) of one primitive of the five fittable kinds (plane, sphere, cylinder,
// cone, torus), chosen at run time, through the closed forms of fit/primitive_jacobians.h: the
// parameter-only quantities are computed once at construction, so one object serves many points.
#pragma once

#include <Eigen/Core>
#include <stdexcept>
#include <variant>
#include <vector>

#include "fit/primitive_jacobians.h"
#include "model/model.h"

namespace implicitfit {

class PrimitiveFunction {
 public:
  // Throws std::invalid_argument for a kind that is not one of the five.
  PrimitiveFunction(NodeType kind, const std::vector<double>& params)
      : f_(Make(kind, params.data())) {}

  // f(x); *grad = grad_x f(x) when grad is not null.
  double operator()(const Eigen::Vector3d& x, Eigen::Vector3d* grad = nullptr) const {
    return std::visit(
        [&](const auto& f) { return f(x.data(), nullptr, grad ? grad->data() : nullptr); }, f_);
  }

 private:
  using Variant =
      std::variant<PrimitiveDistance<PlaneEvaluator>, PrimitiveDistance<SphereEvaluator>,
                   PrimitiveDistance<CylinderEvaluator>, PrimitiveDistance<ConeEvaluator>,
                   PrimitiveDistance<TorusEvaluator>>;
  static Variant Make(NodeType kind, const double* p) {
    switch (kind) {
      case NodeType::kPlane:
        return PrimitiveDistance<PlaneEvaluator>(p);
      case NodeType::kSphere:
        return PrimitiveDistance<SphereEvaluator>(p);
      case NodeType::kCylinder:
        return PrimitiveDistance<CylinderEvaluator>(p);
      case NodeType::kCone:
        return PrimitiveDistance<ConeEvaluator>(p);
      case NodeType::kTorus:
        return PrimitiveDistance<TorusEvaluator>(p);
      default:
        throw std::invalid_argument("PrimitiveFunction: not a fittable primitive kind");
    }
  }
  Variant f_;
};

}  // namespace implicitfit
