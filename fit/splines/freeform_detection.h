// detect --freeform: the stage after primitive detection that turns the smooth regions no
// primitive explains into B-spline surface primitives (fit/splines/bspline_surface_fitter.h),
// with the detector's scales and rules (fit/detect/primitive_detector.h) taken over each part of
// the cloud where the noise varies (fit/splines/local_scales.h: sigma_P, tau_P, theta_P, s_P):
//   1. Regions: the unassigned points, connected over the k-nearest-neighbour graph through
//      pairs whose normals differ by less than max(theta_i, theta_j) (a crease or a fold stops a
//      region); regions under min_points are left as they are, and so are parts whose points
//      fill a volume.
//   2. A region whose normals do not all face one side of its least-squares plane (more than 2%
//      at over 80 degrees from its normal) is counted as folded; it is fitted as the others (the
//      parameter correction follows a moderate fold), and split in two (4.) only if that fails.
//   3. Fit and kind by penalised likelihood, as for the primitives: for each grid in
//      {4, 6, 8, 12, 16, 24, 32, 48, 64} control points along the longer side (the other side in
//      proportion, at least degree + 1; only grids with >= 5 points per control point: a 4 x 4
//      bicubic net fits a region of 80 points), the patch's cost on the region is
//      C = sum_i min(r_i^2 / s_P^2, tau_P^2 / s_P^2) + p ln n, p = 3 n_u n_v, against the cost
//      n tau_P^2 / s_P^2 of leaving every point unassigned; the cheapest patch wins if it beats
//      that (the search stops after two grids that do not improve).
//   4. Support: the region's points within the distance band tau_P and the normal band theta_P
//      (|cos(S_u x S_v, n)| >= cos theta_P), plus those within tau_P whose own normal strays but
//      most of whose region neighbours pass both, cut to their largest connected part; the patch
//      is refitted on it once. Accepted when the support holds >= min_points and its RMS distance
//      is at most 2 s_P (the detector's rule for a primitive); a region failing that is split at
//      the median of its longest principal axis, each half's smooth parts taken again (at most
//      max_depth splits deep), else left unassigned.
//   5. Fringes: the pieces under min_points that an accepted patch leaves of its region (most
//      lie just beyond the patch's rectangle, the domain of its support) are offered to it: one
//      refit on the support and them, kept when its support is larger and its RMS within 2 s_P.
//      What else the patch leaves of the region is taken again from 2.
// Each accepted patch gets the next label; the labels and residuals of the detection are
// extended (residual: the point's signed distance to its patch).
#pragma once

#include <Eigen/Core>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "datasets/clouds/neighbour_graph.h"
#include "model/model.h"

namespace implicitfit {

struct FreeformOptions {
  double noise = 0.0;             // sigma of the detection (> 0)
  double threshold = 0.0;         // tau (> 0)
  double normal_angle_deg = 0.0;  // theta (> 0)
  double spacing =
      0.0;  // s (> 0: each part's bands follow its own noise, fit/splines/local_scales.h)
  int min_points = 10;
  int degree = 3;
  int max_depth = 6;    // splits per region at most
  int num_threads = 0;  // 0: all cores
  // Told a line when the stage starts, every 5 s while it runs (surfaces, points assigned,
  // regions done) and when it ends; empty: silent (the detector's DetectionOptions::progress).
  std::function<void(const std::string&)> progress;
  bool IsValid(std::string* error) const;
};

struct FreeformSurface {
  Model model;              // one bspline_surface node
  std::vector<int> points;  // indices into the cloud, ascending
  double rms_distance = 0.0;
  int count_u = 0, count_v = 0;
  std::string normal_side = "unknown";  // "outward" when the normals follow S_u x S_v on >= 90%
};

struct FreeformResult {
  std::vector<FreeformSurface> surfaces;
  int regions = 0;          // smooth regions of at least min_points found in step 1
  int region_points = 0;    // the points in them
  int splits = 0, fits = 0;
  int grown = 0;   // patches widened over their fringes (step 5)
  int volume = 0;  // parts whose points fill a volume (fit/splines/local_scales.h)
  // Why regions (or their parts) were not accepted: a fold (step 2, counted; split only when the
  // fit fails), no grid beat leaving the points unassigned (step 3), a support under min_points or
  // an RMS over 2 s_P (step 4), and
  // the parts under min_points that splits left (their points stay unassigned), the parts
  // refused at max_depth.
  int folded = 0, no_grid = 0, small_support = 0, rms_over = 0, small_parts = 0, depth_limit = 0;
  int small_part_points = 0;
  // Points left unassigned inside the smooth regions, by the last test that refused them
  // ("depth_limit/<test>" for the parts refused at max_depth; "split_piece", "beside_patch": the
  // smooth parts under min_points that a split or an accepted patch left; "volume": parts
  // filling a volume; "rest_at_depth_limit": beside a patch at max_depth).
  std::map<std::string, int> lost_points;
  double seconds = 0.0;
};

// labels / residuals: the detection's (one per point, -1 unassigned); accepted patches are
// labelled first_label, first_label + 1, ... and their points' residuals set.
FreeformResult DetectFreeformSurfaces(const std::vector<Eigen::Vector3d>& points,
                                      const std::vector<Eigen::Vector3d>& normals,
                                      const NeighbourGraph& neighbours,
                                      const FreeformOptions& options, int first_label,
                                      std::vector<int>* labels, std::vector<double>* residuals);

}  // namespace implicitfit
