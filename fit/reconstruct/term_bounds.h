// Whether one term of a reconstructed solid, the intersection of its positive literals (each a
// one-primitive model, material where f < 0; the negative literals only carve), is bounded,
// decided from the primitives' structure rather than from samples (random far points miss a
// thin tube or a narrow wedge that leaves between them). Used while the expression is built
// (fit/reconstruct/csg_separation.h: a literal is dropped from a term only when the term stays
// bounded). It is the solid verification's own proof (fit/reconstruct/solid_verification.h,
// check 1) applied to one term: {f <= 0} of the sharp intersection is enclosed in convex
// polyhedra (fit/reconstruct/sublevel_enclosure.h: for positive literals of convex primitives,
// supporting half-spaces, no deferred outside literals) and each polyhedron is decided by exact
// linear programming (fit/reconstruct/polytope_box.h) within the limit box. A term is bounded
// when every polyhedron is empty or lies in the limit box, the box the verifier also demands
// (the cloud's box grown by max_reach diagonals), so a term bounded here passes that check too.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "model/model.h"

namespace implicitfit {

// literals[k] a one-node model; `positives` a bit mask over them.
bool TermIsBounded(const std::vector<Model>& literals, std::uint64_t positives,
                   const Eigen::Vector3d& limit_lo, const Eigen::Vector3d& limit_hi);

}  // namespace implicitfit
