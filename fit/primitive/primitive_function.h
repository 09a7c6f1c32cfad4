// f(x) and grad_x f(x) of one primitive of the fittable kinds (fit/primitive/fittable_primitives.h: plane,
// sphere, cylinder, cone, torus), chosen at run time, through the closed forms of
// fit/primitive/primitive_jacobians.h: the parameter-only quantities are computed once at construction, so
// one object serves many points.
#pragma once

#include <Eigen/Core>
#include <stdexcept>
#include <variant>
#include <vector>

#include "fit/primitive/fittable_primitives.h"
#include "model/model.h"

namespace implicitfit {

class PrimitiveFunction {
 public:
  // Throws std::invalid_argument for a kind that is not fittable.
  PrimitiveFunction(NodeType kind, const std::vector<double>& params)
      : f_(Make(kind, params.data())) {}

  // f(x); *grad = grad_x f(x) when grad is not null.
  double operator()(const Eigen::Vector3d& x, Eigen::Vector3d* grad = nullptr) const {
    return std::visit(
        [&](const auto& f) { return f(x.data(), nullptr, grad ? grad->data() : nullptr); }, f_);
  }

 private:
  template <typename Tuple>
  struct DistanceVariant;
  template <typename... E>
  struct DistanceVariant<std::tuple<E...>> {
    using type = std::variant<PrimitiveDistance<E>...>;
  };
  // One alternative per fittable kind (fit/primitive/fittable_primitives.h).
  using Variant = typename DistanceVariant<FittableEvaluators>::type;
  static Variant Make(NodeType kind, const double* p) {
    return VisitFittablePrimitive(
        kind, [p](auto e) -> Variant { return PrimitiveDistance<decltype(e)>(p); });
  }
  Variant f_;
};

}  // namespace implicitfit
