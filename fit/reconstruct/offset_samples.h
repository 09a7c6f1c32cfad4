// The inside and outside samples of one boundary point for the separation of `reconstruct`
// (fit/reconstruct/csg_separation.h), with an offset that shrinks where the material (or the empty space)
// beside the point is thinner than the offset.
//
// A point p on literal k's surface with outward normal n (outward of the solid) stands for the
// cell of the arrangement just inside it and the cell just outside it. The fixed samples p - t n
// and p + t n (t = 1% of the diagonal) land in those cells only when no other literal's surface
// lies within t of p along n. Where one does (a flange rim narrower than t beside a dome, a
// concave fillet between a stem and a ball, a small bore), the fixed sample lands in the cell
// beyond it and votes there, and the thin cell gets no sample: the separation then drops the
// literal that bounds it (Fit4CAD PC34's rim cylinder, PC124's fillet torus).
// Adaptive offset: p is projected onto literal k's surface along its gradient (one Newton step,
// p' = p - f_k grad f_k / |grad f_k|^2, so that noise across the surface cannot put the sample
// on the wrong side of literal k), and d = +-grad f_k / |grad f_k| is the side n points to. For
// each side (s = -1 inside, +1 outside), the sign vector of all literals at p' + s (t / 64) d is
// the reference (the cell adjacent to p); the ray p' + s u d, u in (t / 64, t], is marched in
// 16 steps and the first change of the sign vector is located by bisection at u = c. No change:
// the fixed sample p + s t n is kept (the result is the one of the fixed offset). A change: the
// sample is p' + s (t / 64 + c) / 2 d, between the reference and the crossing: in the adjacent
// cell, at the largest offset the local thickness allows (half of it).
#pragma once

#include <Eigen/Core>
#include <vector>

#include "model/model.h"

namespace implicitfit {

struct OffsetSamplePair {
  Eigen::Vector3d inside = Eigen::Vector3d::Zero(), outside = Eigen::Vector3d::Zero();
  bool inside_adapted = false, outside_adapted = false;  // the offset was shortened
};

// p on literals[k]'s surface with the oriented normal n (unit, outward of the solid); t > 0.
// adaptive false: the fixed samples p -+ t n.
OffsetSamplePair OffsetSamples(const Eigen::Vector3d& p, const Eigen::Vector3d& n, int k,
                               const std::vector<Model>& literals, double t, bool adaptive = true);

}  // namespace implicitfit
