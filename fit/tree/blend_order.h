// The order of a smooth n-ary operator's children (part of step 5 of `implicitfit reconstruct`,
// fit/reconstruct/blend_refit.h).
//
// A smooth union or intersection of k > 2 children is a left fold of the binary blend,
// f = B(...B(B(f_1, f_2), f_3)..., f_k), and B is not associative: where three or more children
// are active together (a box's corner: one face of each axis), the zero set depends on the order
// in which they are folded. On a rounded box's truth (6 planes, delta 0.2, epsilon 0.12), the
// same tree with its children in another order differs from it by up to 0.0074 at the corners
// (RMS 0.0006-0.0009 over the surface), more than the fit's noise. detect gives the faces in an
// arbitrary order, so the order is a discrete parameter of the model to be chosen from the data.
//
// ChooseChildOrders improves it by local search: for every smooth union / intersection of the
// model with at least 3 children (a difference keeps its minuend first and is left alone), swap
// two children (every pair), and keep the swap when it lowers the truncated cost
// sum_i min(d_i^2, clip^2) (d_i = f / |grad f|) at the points where the order can matter (three
// or more children within delta of the largest, for a union of the smallest; at least 10 such
// points, or the order is left), with epsilon the best of the
// current one and {0.3, 0.6, 0.9} delta (the fitted epsilon adapts to the order it was fitted
// with); repeat until no swap helps or 4 k passes. The parameters are left as they are (epsilon
// included; a swap must gain more than 1e-6 clip^2 per point): the caller refits them for the
// new order.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "model/model.h"

namespace implicitfit {

// sum_i min(d_i^2, clip^2) with d_i = |f| / |grad f| (MSAC's truncated quadratic): the cost by
// which both the order search and the blend refit (blend_refit.cc) compare two solids.
double TruncatedCost(const Model& m, const std::vector<Eigen::Vector3d>& points, double clip);

// True when some operator's children were reordered.
bool ChooseChildOrders(Model* m, const std::vector<Eigen::Vector3d>& points, double clip);

}  // namespace implicitfit
