// One entry per primitive kind the primitive fitter fits (plane, sphere, cylinder, cone,
// torus): the fit side of the kind's row in model/primitives/primitive_kinds.h.
//   evaluator       FittableEvaluators below, in the same order as FittablePrimitives(); its
//                   closed-form distance PrimitiveDistance<E> (fit/primitive/primitive_jacobians.h) is
//                   what the fitter's residuals and inlier tests evaluate
//   sample_size     oriented points in a minimal sample (RANSAC's m)
//   from_sample     the hypothesis from such a sample (fit/primitive/minimal_samples.h); false when the
//                   sample is degenerate
//   from_points     whether fit/metrology/point_hypotheses.h hypothesises it from points alone (no
//                   normals)
// Everything else (names, fields and their roles, recentring, bounds, degrees of freedom) the
// code reads from model/primitives/primitive_kinds.h.
#pragma once

#include <stdexcept>
#include <string>
#include <tuple>
#include <type_traits>
#include <vector>

#include "fit/primitive/minimal_samples.h"
#include "fit/primitive/primitive_jacobians.h"
#include "model/model.h"

namespace implicitfit {

using HypothesisFromSample = bool (*)(const Vec3* points, const Vec3* normals,
                                      std::vector<double>* params);

struct FittablePrimitive {
  NodeType type;
  int sample_size;
  HypothesisFromSample from_sample;
  bool from_points;
};

// The evaluators of the fittable kinds, in the order of FittablePrimitives().
using FittableEvaluators =
    std::tuple<PlaneEvaluator, SphereEvaluator, CylinderEvaluator, ConeEvaluator, TorusEvaluator>;

inline const std::vector<FittablePrimitive>& FittablePrimitives() {
  static const std::vector<FittablePrimitive> kinds = {
      {NodeType::kPlane, 1,
       [](const Vec3* p, const Vec3* n, std::vector<double>* h) {
         return PlaneFromSample(p[0], n[0], h);
       },
       true},
      {NodeType::kSphere, 2, SphereFromSample, true},
      {NodeType::kCylinder, 2, CylinderFromSample, true},
      {NodeType::kCone, 3, ConeFromSample, true},
      {NodeType::kTorus, 7,
       [](const Vec3* p, const Vec3* n, std::vector<double>* h) {
         return TorusFromSample({p, p + 7}, {n, n + 7}, h);
       },
       true},
  };
  return kinds;
}

// The entry of a fittable kind; nullptr for any other node type.
inline const FittablePrimitive* FindFittablePrimitive(NodeType type) {
  for (const FittablePrimitive& kind : FittablePrimitives())
    if (kind.type == type) return &kind;
  return nullptr;
}

// f(E{}) for the evaluator E of a fittable kind (e.g. to instantiate a template on it);
// std::invalid_argument for any other kind.
template <size_t I = 0, typename F>
std::invoke_result_t<F, std::tuple_element_t<0, FittableEvaluators>> VisitFittablePrimitive(
    NodeType kind, F&& f) {
  if constexpr (I == std::tuple_size_v<FittableEvaluators>) {
    throw std::invalid_argument(std::string("not a fittable primitive kind: ") +
                                NodeTypeName(kind));
  } else {
    if (kind == FittablePrimitives()[I].type)
      return f(std::tuple_element_t<I, FittableEvaluators>{});
    return VisitFittablePrimitive<I + 1>(kind, std::forward<F>(f));
  }
}

}  // namespace implicitfit
