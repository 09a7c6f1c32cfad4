// Guo's object of a Bernstein patch is S(f) ∩ V, the solid restricted to the patch's
// tetrahedron V: outside V the polynomial is an extrapolation (a cubic certified convex on V
// may bend the other way beyond it). `mesh --clip-to-tetrahedron` and `eval
// --clip-to-tetrahedron` evaluate that object: every bernstein_patch node P of the model is
// replaced by the sharp intersection (order 0, max) of P and the four planes of its
// tetrahedron's faces (outward normals, offsets through the face: a plane's f is the signed
// distance to the face plane), so {f <= 0} becomes {f_P <= 0} ∩ V exactly and the surface
// closes along V's faces. The rest of the tree is kept as it is. Done on the model's JSON form
// (model/file/model_json.h), so every node kind passes through unchanged.
#pragma once

#include "model/model.h"

namespace implicitfit {

// The rewritten model; *clipped receives the number of patches clipped (0: the model is
// returned unchanged).
Model ClipPatchesToTetrahedra(const Model& model, int* clipped);

}  // namespace implicitfit
