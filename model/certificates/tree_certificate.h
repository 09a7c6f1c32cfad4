// Convexity certificate of a whole model tree (docs/maths.md LP-4 c), bottom-up by rules.
//
// Classes, from strongest to weakest:
//   kConvexFunction  f itself is convex (on `domain`), hence also the solid {f <= 0};
//   kConvexSolid     the solid {f <= 0} is convex, f is not certified convex;
//   kNotCertified    no rule applies (the solid may or may not be convex).
// Leaves:
//   plane (affine), sphere, cylinder, cone (exact signed distance to a convex single nappe):
//     convex function everywhere;
//   bernstein_patch certified by A^mu (model/certificates/convexity_certificate.h): convex function on its
//     tetrahedron only (`domain` names it); degree 1: convex function (affine) everywhere;
//   bernstein_mesh certified convex on its box (model/certificates/bernstein_mesh_certificate.h: every
//     tetrahedron's A^mu positive definite and C1 across the faces): convex function on the box
//     only (`domain` names it);
//   ellipsoid (first-order distance, not convex far from the surface), quadric with A >= 0
//     (f = q / |grad q|): convex solid;
//   box (exact SDF), paraboloid with curvature >= 0, skeleton_offset of one point or segment:
//     convex function everywhere;
//   torus, quadric with A indefinite, uncertified patch, paraboloid with curvature < 0,
//   skeleton_offset of several elements, blobs, complement, partition, uncertified mesh: not
//   certified.
//   bspline_volume certified per cell (model/splines/bspline_volume_certificate.h): convex function
//     on its box (`domain` names it); bspline_surface: not certified.
// morph t f_A + (1 - t) f_B of two convex functions: convex function (convex combination).
// Operators (n = order; children fold left to right, so the rule is applied to all children):
//   intersection, n = 0 (sharp max, any smoothing): max of convex functions is convex; the
//     intersection of convex solids is convex;
//   intersection, "smoothing": "convex", n >= 1: S^c_max is convex and nondecreasing in both
//     arguments, so S^c_max of convex functions is convex (convex solids alone: not certified);
//   intersection with Li-Phillips smoothing (n >= 1): not certified (S_max is neither convex
//     nor monotone, docs/maths.md LP-4 a); union, difference: not certified.
// A convex function on domain D certifies the solid within D; domains combine by intersection
// (a patch's tetrahedron, a mesh's box: both convex, so their intersection is convex).
#pragma once

#include <string>
#include <vector>

#include "model/model.h"

namespace implicitfit {

enum class TreeConvexity { kConvexFunction, kConvexSolid, kNotCertified };

// "convex-function" | "convex-solid" | "not-certified".
const char* TreeConvexityName(TreeConvexity c);

struct NodeCertificate {
  TreeConvexity convexity = TreeConvexity::kNotCertified;
  std::string rule;                 // why, in words (the leaf class or the operator rule)
  std::vector<int> domain_nodes;  // f convex only within the domains of these nodes (a
                                  // bernstein_patch's tetrahedron, a bernstein_mesh's or a
                                  // bspline_volume's box), their intersection; empty: everywhere
};

// One certificate per node of the model, indexed like Model::nodes().
std::vector<NodeCertificate> CertifyTree(const Model& model);

}  // namespace implicitfit
