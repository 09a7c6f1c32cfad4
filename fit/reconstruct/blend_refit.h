// Step 5 of `implicitfit reconstruct` (fit/reconstruct/solid_reconstruction.h): the joint
// refinement of the smooth operators (blends) of a reconstructed solid and of the faces they join.
//
// Free parameters: delta and epsilon of every smooth operator and the primitives that are its
// direct children (the faces its fillet joins); every other primitive keeps the primitive
// fitter's parameters (under sharp operators a point's residual depends on the one active
// primitive, already fitted to its own points; primitives deeper under a smooth operator are
// copies inside CSG terms). Operators above a smooth one are sharp (order 0) and pass one child's
// value through unchanged (max, min, or the negated subtrahend), so wherever the solid's value
// equals, up to sign, the value of a top-level smooth operator's subtree, the solid's residual is
// that subtree's, and elsewhere it does not depend on the subtree's parameters at all. Each such
// subtree is therefore fitted alone (fit/tree/tree_fitter.h), as its own model, on the near
// points where |f_solid| = |f_subtree| (relative 1e-9): the same least-squares problem as the
// whole tree's, without evaluating the other terms of the union at every point and every Jet
// pass (a points-only rounded box: one smooth term of eight, 58 s of tree fit before). At most
// max_points of those points are used: all that no primitive was assigned (the fillets'
// transition points, which carry delta and epsilon), then a random share of the others.
// The figures (sigma = 1.4826 median |d|, RMS of the inliers |d| < max(3 sigma, floor), d = f /
// |grad f|) are those of the whole solid at all the near points.
#pragma once

#include <Eigen/Core>
#include <random>
#include <vector>

#include "fit/tree/tree_fitter.h"
#include "model/model.h"

namespace implicitfit {

// Copies the subtree of src at `index` into dst (parameters, order, fixed fields); returns the
// new node's index. map (optional, sized src.nodes().size()) receives map[src node] = dst node.
int CopySubtree(const Model& src, int index, Model* dst, std::vector<int>* map = nullptr);

// Marks the primitives that are not direct children of a smooth operator fixed; true when some
// parameter is left free.
bool FixPrimitivesOutsideBlends(Model* m);

// The figures above for a model as it is (success true, nothing fitted).
TreeFitResult TreeFigures(const Model& m, const std::vector<Eigen::Vector3d>& points,
                          const std::vector<Eigen::Vector3d>& normals, double floor);

// The refinement of the header. assigned[i]: near point i lies on a primitive. Returns the fitted
// solid in .model; success false (and the fitter's message) when a subtree's fit failed.
TreeFitResult RefitBlends(const Model& solid, const std::vector<Eigen::Vector3d>& points,
                          const std::vector<Eigen::Vector3d>& normals,
                          const std::vector<bool>& assigned, int max_points, double floor,
                          const TreeFitOptions& options, std::mt19937_64* rng);

}  // namespace implicitfit
