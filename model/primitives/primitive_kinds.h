// One entry per primitive kind: a leaf of the model tree whose parameters are one fixed-size
// vector (plane, sphere, cylinder, cone, torus, ellipsoid, quadric, box, paraboloid). The entry
// holds everything the code common to all primitives needs, so that it never switches on the
// kind:
//   name            the JSON "type" (NodeTypeName, NodeTypeFromName)
//   fields          the named groups of parameters in flat-vector order, each with its role
//                   (model/model.h FieldRole): the model JSON reads and checks them by role,
//                   the fitters bound them (positive lengths, angles) and put directions on
//                   SphereManifold<3> by role, recentring moves positions by role
//   sampling_box    an axis-aligned box around the part of the surface `sample` and `mesh`
//                   draw from (datasets/generators/model_sampler.h)
// The fit side of a kind (closed-form derivatives, hypotheses from a minimal sample, the
// sample size) is its row in fit/primitive/fittable_primitives.h.
// Adding a primitive kind: docs/library.md, "Adding a primitive kind".
#pragma once

#include <Eigen/Core>
#include <vector>

#include "model/model.h"

namespace implicitfit {

struct PrimitiveKind {
  NodeType type;
  const char* name;
  std::vector<ParameterField> fields;
  // The box [lo, hi] for the parameters p (flat layout of the kind's evaluator).
  void (*sampling_box)(const double* p, Eigen::Vector3d* lo, Eigen::Vector3d* hi);
};

// Every primitive kind, one entry each.
const std::vector<PrimitiveKind>& PrimitiveKinds();
// The entry of a primitive kind; nullptr for any other node type (operators, patches, ...).
const PrimitiveKind* FindPrimitiveKind(NodeType type);

// How many numbers of the field shape the surface: a direction 2 (its length does not count),
// an axis point 2 (it slides along the axis), a rotation 3, any other field its size.
int DegreesOfFreedom(const ParameterField& field);

// The first field with this role in a field list (its offset in *offset); false when none.
bool FindFieldWithRole(const std::vector<ParameterField>& fields, FieldRole role, int* offset);

}  // namespace implicitfit
