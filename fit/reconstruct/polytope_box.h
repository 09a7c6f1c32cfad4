// What a convex polyhedron {x : n_i . x <= d_i} is, decided exactly: empty, bounded within a
// given limit box (and its axis-aligned box), or reaching beyond the limit (unbounded, or
// bounded only far away), by linear programming. For each coordinate a and direction +-1,
// maximise +-x_a over the half-spaces: GLPK's primal simplex finds a basis in double precision
// and glp_exact re-solves from it in rational arithmetic (the doubles n_i, d_i taken as exact
// rationals), so "infeasible", "unbounded" and the optimum are exact for the given half-spaces.
// The limit matters because the half-spaces are rounded: the eight faces of the prism about a
// cylinder are orthogonal to its axis only to ~1e-17, so an open tube capped by nothing is, in
// exact arithmetic on those doubles, a pyramid closed ~1e17 away. A polyhedron that leaves the
// limit box is reported with witnesses: its deepest points beyond the limit (the centre of the
// largest ball in it there, r in [0, limit's diagonal], the Chebyshev centre), so that the
// witness of a tube lies on its axis rather than at a corner of its prism.
// Why GLPK: a maintained Debian LP library with an exact simplex (already the minimum-zone
// solver's, fit/metrology/chebyshev_lp.h), where a hand-written vertex enumeration would need
// its own tolerance to tell an empty or unbounded polyhedron from a thin one.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "fit/reconstruct/sublevel_enclosure.h"

namespace implicitfit {

enum class PolytopeExtent { kEmpty, kBounded, kBeyondLimit, kUnsolved };

struct PolytopeBox {
  PolytopeExtent extent = PolytopeExtent::kUnsolved;
  // kBounded: the box, padded outward by 1e-9 (1 + |bound|) against the final rounding.
  Eigen::Vector3d lo = Eigen::Vector3d::Zero(), hi = Eigen::Vector3d::Zero();
  // kBeyondLimit: each signed coordinate direction it leaves the limit box along, whether it
  // is unbounded that way, and its deepest points beyond the limit that way: at the limit and
  // 1, 4, 16, 64 times the limit box's diagonal farther (as far as the polyhedron goes), since
  // the solid inside the polyhedron may leave and come back (a tube through a sphere's outside).
  struct Exit {
    Eigen::Vector3d direction = Eigen::Vector3d::Zero();
    std::vector<Eigen::Vector3d> witnesses;
    bool infinite = false;
  };
  std::vector<Exit> exits;
  std::string message;  // kUnsolved: GLPK's status
};

PolytopeBox BoundPolytope(const std::vector<HalfSpace>& faces, const Eigen::Vector3d& limit_lo,
                          const Eigen::Vector3d& limit_hi);

}  // namespace implicitfit
