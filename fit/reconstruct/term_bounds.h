// Whether one term of a reconstructed solid, the intersection of its positive literals (each a
// one-primitive model, material where f < 0; the negative literals only carve), is bounded,
// decided from the primitives' structure rather than from samples (random far points miss a
// thin tube or a narrow wedge that leaves between them). Used while the expression is built
// (fit/reconstruct/csg_separation.h: a literal is dropped from a term only when the term stays
// bounded), not as the solid's verification.
//
// A convex set's unbounded directions form its recession cone; the intersection's cone is the
// intersection of the literals' cones:
//   sphere, torus, ellipsoid, box: {0} (bounded; the term is);
//   cylinder (axis a): the line through +-a;
//   cone (single nappe, axis u into the opening, half angle alpha): {v : u . v >= cos(alpha) |v|};
//   plane n . x <= d: {v : n . v <= 0}.
// The term is taken as unbounded when some unit v has n . v <= eps for every plane and lies in
// every cylinder's line and every cone (eps = sin 1 deg: a wedge that closes only a hundred
// sizes away is no bounded part). With a cylinder the candidates are +-a. With planes only,
// v minimises g(v) = max_i n_i . v over the sphere; the minimum of a maximum of linear functions
// on the unit sphere is reached where one, two or three of them are active: v = -n_i, v along
// -(n_i + n_j), or v along +-(n_j - n_i) x (n_k - n_i); the term is unbounded when g <= eps at one
// of them. With cones (and no cylinder), the candidates are those, the cones' axes and, for
// every plane, the two rays of each cone's surface on which n . v = 0 (where the boundaries of
// the two cones meet); a candidate must satisfy every constraint. Other kinds (none occur among
// reconstruct's literals) count as unbounded.
#pragma once

#include <cstdint>
#include <vector>

#include "model/model.h"

namespace implicitfit {

// literals[k] a one-node model; `positives` a bit mask over them.
bool TermIsBounded(const std::vector<Model>& literals, std::uint64_t positives);

}  // namespace implicitfit
