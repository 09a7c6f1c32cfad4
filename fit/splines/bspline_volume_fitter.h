// Fitting a bspline_volume (model/splines/bspline_volume.h) to an oriented cloud (fit --model
// bspline-volume --cells n [--degree k] [--convex]; docs/maths.md TB-3).
//
// Box: the cloud's box grown on every side by max(5% of its extent, box_margin x the longest
// extent) (5% of the longest with convex), split into cubes of edge h = longest grown extent /
// cells, n_a = ceil(extent_a / h) per axis, centred on the box.
// 1. Linear start, one sparse least-squares problem in the coefficients c (f is linear in c), as
//    for the patches: f(p_i) = 0 and f(p_i +- d n_i) = +-d (d = 1% of the box diagonal); far-field
//    rows at a lattice of spacing h/2 farther than 2d from every point (brute force over at most
//    5000 points): f(x) = s |x - p| with p the nearest point and s the side from the cloud's
//    generalised winding number (fit/bernstein/winding_number.h: inside where w > 1/2), +|x - p|
//    on the box faces, so the zero set closes inside the box; their weight grows linearly with
//    the distance to the data up to one cube edge, times far_field_weight; smoothing rows
//    lambda (the second differences of c along each axis and the mixed ones, weights 1 and 2:
//    the discrete thin-plate energy; lambda = smoothing x rows per coefficient) make the system
//    definite where no data reaches. Normal equations by sparse Cholesky (Eigen).
// 2. Refinement: Gauss-Newton on r_i = f(p_i) / |grad f(p_i)| with |grad f| frozen at the
//    current iterate (iteratively reweighted rows B(p_i) c / g_i = 0), the offset rows at weight
//    0.1 (they fix f's scale, which r leaves free), the far-field and smoothing rows; while the
//    RMS improves by more than 0.5% (at most max_iterations); the best iterate is kept.
// 3. convex: the start is the certified convex quadric of the degree-2 Bernstein patch fit
//    (fit/bernstein/patch_fitter.h), which the spline space holds exactly (degree >= 2):
//    interpolated at the Greville points, axis by axis. Every refinement step c -> c' is taken
//    as c + alpha (c' - c) with the largest alpha in {1, 1/2, ..., 1/64} whose volume the
//    certificate (model/splines/bspline_volume_certificate.h) accepts with the margin 1e-6 x
//    the start's smallest eigenvalue and whose RMS is lower (the certified set is convex in c,
//    so the segment from a certified c is certified up to some alpha); no far-field rows (a
//    convex f has one sublevel component). The result is certified again; if that fails, the
//    fit fails. The unconstrained fit is also run, for its RMS (the price of convexity).
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "fit/common/fit_summary.h"
#include "model/model.h"
#include "model/splines/bspline_volume_certificate.h"

namespace implicitfit {

struct VolumeFitOptions {
  int degree = 3;                 // 1..SplineLimits::kMaxVolumeDegree (convex: >= 2)
  int cells = 8;                  // along the longest side of the grown box
  bool convex = false;
  double smoothing = 1e-3;        // lambda / rows per coefficient
  double far_field_weight = 1.0;  // 0: no far-field rows
  double box_margin = 0.1;
  int max_iterations = 30;
  bool IsValid(std::string* error) const;
};

struct VolumeFitResult : FitSummary {
  SplineStructure structure;
  std::vector<double> coefficients;
  double rms = 0.0;                 // RMS of f / |grad f| over the points
  double initial_rms = 0.0;         // after the start
  double unconstrained_rms = -1.0;  // convex: the unconstrained fit's RMS
  double mean_normal_angle_deg = -1.0;
  int iterations = 0;
  bool certified_convex = false;
  VolumeConvexityCertificate certificate;  // convex only
  Model ToModel() const;
};

VolumeFitResult FitBSplineVolume(const std::vector<Eigen::Vector3d>& points,
                                 const std::vector<Eigen::Vector3d>& normals,
                                 const VolumeFitOptions& options);

}  // namespace implicitfit
