// A proof that a solid is bounded, from the structure of its tree: the set {x : f(x) <= s} is
// enclosed in a union of convex polyhedra, each given by half-spaces n . x <= d, built bottom up
// from bounds that hold for every x (no sampling: a thin infinite tube cannot hide between
// samples). fit/reconstruct/polytope_box.h then decides each polyhedron exactly (empty,
// bounded with its box, or unbounded) by linear programming.
//
// Write E(g, t) for an enclosure of {g <= t}; a node is entered with a sign sigma = +-1 and
// encloses {sigma f <= t} (sigma = -1: the superlevel set {f >= -t}, needed for subtrahends).
// Primitives (sigma = +1), from lower bounds of f by supporting half-spaces:
//   plane       f = n^ . x - d': {n^ . x <= d' + t} (sigma = -1: {-n^ . x <= -d' + t})
//   sphere, box, cylinder, cone: f is the exact signed distance to a convex set K, so for every
//               half-space H = {w . (x - c) <= r} holding K, f >= w . (x - c) - r (a distance
//               to a superset is smaller): sphere 14 faces (axes, diagonals) at r + t, box its 6
//               faces, cylinder an octagonal prism about the axis (radius + t; infinite along
//               it), cone 8 planes through the apex with normals cos(a) w - sin(a) u (a pyramid
//               holding the nappe; infinite along the axis)
//   torus       f = sqrt((rho - R)^2 + h^2) - r >= max(|h|, rho - R) - r: the slab |h| <= r + t
//               and the octagonal prism rho <= R + r + t
//   ellipsoid   f = g / |grad g|, g = |y| - 1, |grad g| <= 1 / r_min, so f >= (|y| - 1) r_min
//               outside: |e_i . (x - c)| <= r_i (1 + max(t, 0) / r_min)
//   paraboloid  f = h + (kappa / 2) |w|^2 >= h when kappa >= 0: {h <= t} (sigma = -1 and
//               kappa <= 0: {-h <= t})
//   other kinds: all of space (no bound).
// The outside of a convex primitive (sigma = -1: {f >= -t}) is not convex, so it is not made
// into faces at once: it is deferred (EnclosurePiece::outside). K_t = {f < -t} (the inner
// parallel body: a ball of radius r - t, a cylinder of radius r - t, the cone moved t / sin(a)
// along its axis, the box shrunk by t; for the ellipsoid |y| < 1 - t / r_min, since there
// f <= (|y| - 1) r_min) holds an inscribed convex polyhedron I (octagonal prism, pyramid of 8
// generators, box, cube with vertices on the ball or the ellipsoid's |y| = s sphere), and
// {f >= -t} lies in the complement of I, the union of the half-spaces n_i . x >= d_i over I's
// faces. SplitOnOutside replaces a piece's first deferred literal by those half-spaces: one
// piece per face (none of them is needed unless the piece alone is unbounded: a cylinder minus a
// coaxial wider bore, a wedge of planes minus a cone that swallows its far part).
// Operators fold left to right, op(op(c0, c1), c2); with subtrahends negated (difference:
// c0, -c1, -c2, ...) every step is max-like or min-like. Li & Phillips' S_abs satisfies
// |t| <= S_abs(t) <= |t| + delta / 2 (when 0 < epsilon <= delta: in the parabolic zone
// S_abs - |t| = (|t| - delta)^2 / (2 delta) <= delta / 2, in the rising zones a convex
// combination of that parabola and |t|, beyond delta + epsilon exactly |t|); the convex S^c_abs
// satisfies it too (it is |t| beyond w = delta, 1-Lipschitz and convex, so S^c_abs - |t| is
// largest at 0, S^c_abs(0) <= w / 2). Hence with the reach r = delta / 4 (0 when sharp):
//   max(a, b) <= S_max(a, b) <= max(a, b) + r,   min(a, b) - r <= union(a, b) <= min(a, b),
// and for k children:
//   intersection, difference (max-like):  E(f, t) = intersection over children of E(c, t)
//                                          E(-f, t) = union over children of E(-c, t + (k-1) r)
//   union (min-like):                      E(f, t) = union over children of E(c, t + (k-1) r)
//                                          E(-f, t) = intersection over children of E(-c, t)
//   complement: E(-child) for E(f) and the reverse.
// An intersection of unions is the union of the pairwise intersections; past max_pieces the
// enclosure gives up (all of space: not proven).
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "model/model.h"

namespace implicitfit {

struct HalfSpace {
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();  // not necessarily unit
  double offset = 0.0;                                // the set normal . x <= offset
};

// One convex polyhedron of the enclosure: the intersection of its faces (none: all of space).
struct EnclosurePiece {
  std::vector<HalfSpace> faces;
  std::string label;  // the literals it comes from, e.g. "p3 & !p7"; "!" = superlevel side
  std::string unbounded_reason;  // the nodes on the way that gave no bound (e.g. "a quadric")
  // Deferred literals {f_node >= -level} of convex primitives (see above).
  struct Outside {
    int node = 0;
    double level = 0.0;
  };
  std::vector<Outside> outside;
};

struct SublevelEnclosure {
  std::vector<EnclosurePiece> pieces;  // {f <= level} lies in their union (none: f > level)
  bool overflow = false;               // gave up past max_pieces
};

SublevelEnclosure EncloseSublevel(const Model& model, double level = 0.0, int max_pieces = 512);

// The piece with its first deferred literal replaced by the faces of the complement of the
// literal's inscribed polyhedron: one piece per face, or the piece without the literal when
// {f >= -level} is all of space (K_t empty). Precondition: !piece.outside.empty().
std::vector<EnclosurePiece> SplitOnOutside(const Model& model, const EnclosurePiece& piece);

}  // namespace implicitfit
