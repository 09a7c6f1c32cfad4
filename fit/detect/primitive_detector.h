// Detection of every primitive (plane, sphere, cylinder, cone, torus) in one oriented cloud,
// with its points: the library side of `implicitfit detect`.
//
// Scales from the data (nothing absolute):
//   s     the sampling spacing (median 6th-neighbour distance, given with the neighbourhoods);
//   sigma the noise: 1.4826 x the median over points of the median |(n_i + n_j) / 2 . (p_j - p_i)|
//         over their first 8 neighbours j: the distance of the neighbours to the point's tangent
//         plane without the surface's sagitta (fit/detect/surface_noise.h; the tangent-plane distance
//         read 0.18 on a noise-free coarse CAD sample, so the bands were 3 times too wide);
//   tau   the distance band: max(3 sigma, 0.1 s) unless options.threshold is given;
//   theta the normal band: max(20 deg, 3 x the median angle between neighbouring normals),
//         at most 45 deg.
// A cloud whose tangent-plane noise (1.4826 x median of the median |n_i . (p_j - p_i)|) exceeds 0.4
// s and whose neighbouring normals differ by more than 15 deg (median) fills a volume (uniform
// random points: 0.58 s, > 15 deg) and gives no primitive unless options.threshold is given. A
// point supports a primitive when |f(x)| < tau and |cos(grad f, n)| >= cos(theta).
//
// Candidates (local sampling, so small primitives are found among large ones): a seed point is
// drawn among the unassigned ones whose normal agrees with its neighbours' (not on a crease);
// its patch is the first `patch_size` unassigned points reached from it over the k-nearest-
// neighbour graph. For every allowed kind, the fit to the whole patch (fit/detect/patch_hypotheses.h)
// and minimal samples of the patch's oriented points (fit/primitive/minimal_samples.h) give hypotheses;
// the best-supported one on the patch (ties: the smallest sum of squared residuals) is refitted
// to its patch support
// (fit/detect/local_primitive_refit.h), then grown from it over the neighbour graph: the support is the
// set of unassigned points connected to the patch through supporting points (connected at the
// sampling density), refitted and regrown while it grows, and least-squares fitted at the end.
// A kind's candidate whose RMS exceeds 2 sigma (a wrong surface crossing the band spreads its
// residuals over it; a right one grown past a tangent joint too) is grown again in half the band;
// it is dropped if its RMS still exceeds 2 sigma or when it lies more than 10 cloud diagonals
// away (degenerate; a cylinder's distance is its axis line's).
// Kind (penalised likelihood): on the union U of the kinds' supports, each kind's cost is the
// truncated-Gaussian (MSAC) negative log-likelihood plus the BIC penalty,
//   C_k = sum_{i in U} min(r_ik^2 / s^2, tau^2 / s^2) + p_k ln |U|,
// with s = sigma clamped to [tau / 10, tau / 3] and p_k the kind's degrees of freedom (plane 3,
// sphere 4, cylinder 5, cone 6, torus 7); the smallest cost wins. Then the simplest kind that
// explains (within both bands) at least 97% as many points of U as the winner replaces it:
// differences below the detection tolerance buy no parameters, so a plane beats a huge-radius
// sphere or cylinder unless the curved surface explains more than 3% more of the points. A
// curved simpler kind must also cost (C_k) at most 2 times the winner's: a sphere through a short
// cylindrical band explains its points within the band but leaves the sagitta in its residuals.
// Split test (tangent joints): a curved winner W that grew across a tangent-continuous joint
// (a torus over a cylinder and its fillet, a flat cone over the faces at a polyhedron's vertex)
// is compared with alternatives made of simpler kinds: each of the seed's simpler candidates,
// plus up to two simpler primitives grown on what it leaves of U (growth restricted to U);
// each point costs its smallest truncated residual over the pieces, plus the pieces' BIC
// penalties. When an alternative costs less than W, the seed's candidate is its first piece.
// Rounds: `seeds_per_round` seeds (each with its own RNG seeded from the seed, the round and its
// index, so the result does not depend on the thread count) are evaluated in parallel; their
// candidates are accepted greedily by support size, each keeping its still-unassigned points
// when at least 80% of them remain. Detection stops when no seed is left or after
// ln(0.01) / ln(1 - m / R) failed seeds in a row (a primitive of m = min_points points among R
// remaining ones would have been seeded with 99% probability).
// Leftover pass: the points still free then get normals re-estimated from their free neighbours
// only (fit/detect/restricted_normals.h: the faces beside a narrow surface no longer smear them), and the
// rounds run again with seeds among them (seedable against their free neighbours, at least 3);
// points it leaves free get their original normals back. (Fit4CAD PC34: a cylinder ring two rows
// high between a plane and a dome has no seedable point in the first pass.)
// Band cylinder: a seed's sphere whose support a cylinder fits within the RMS rule (axis along
// the support's least spread, least-squares refitted, RMS <= 2 sigma) is a narrow band around a
// circle, whose curvature across does not tell a sphere from a cylinder (only the BIC penalty
// picked the sphere): the cylinder is taken. The final kind checks do not turn a cylinder into
// a sphere that coincides with it along a great circle (centre on the axis, equal radii within
// tau).
// Final stage: each primitive is replaced by the simplest kind that explains 97% as many of its
// points (hypotheses from its whole support and minimal samples; curved kinds within 2 times the
// cost); pieces of one surface are merged (same kind,
// adjacent, each explaining >= 80% of the other's points); each curved primitive's kind is
// checked against its neighbours: every other kind Q is fitted to its support S (least squares on
// the points Q supports) and each model M scored by C_M = sum_{i in S} min(r_iM^2, r_iO^2, tau^2)
// / s^2 + p_M ln |S|, r_iO the residual of any other primitive O that supports i; a Q that
// supports fewer points of S than the primitive (it over-reached into a neighbour: a sphere over a
// short cylinder and its chamfer) replaces it when cheaper; every point is re-assigned to the
// primitive explaining it best (|f| < tau; among those with agreeing normals the smallest |f|,
// else, for points next to a primitive's support, the smallest |f| whatever the normal: creases
// where estimated normals are smeared; |f| within sigma of each other, a point on the joint of
// two surfaces, go to the normal closer to grad f; a sphere's or cylinder's candidates include
// the rest of its ball or circle beyond the support's box); a plane's support is cut to its
// largest connected component (a merged plane's, and a curved primitive's, keep every part of
// min_points: a narrow ring falls into arcs over the neighbour graph, whose links run to the
// faces beside it); primitives under min_points are dropped; every primitive gets the maximum-likelihood
// refinement of `fit` on its points (fit/primitive/primitive_fitter.h, Ceres, with standard deviations).
#pragma once

#include <Eigen/Core>
#include <functional>
#include <string>
#include <vector>

#include "model/model.h"
#include "datasets/clouds/neighbour_graph.h"

namespace implicitfit {

struct DetectionOptions {
  std::vector<NodeType> kinds = {NodeType::kPlane, NodeType::kSphere, NodeType::kCylinder,
                                 NodeType::kCone, NodeType::kTorus};
  double threshold = 0.0;         // distance band tau; <= 0: from the data (see above)
  double normal_angle_deg = 0.0;  // normal band theta; <= 0: from the data
  int min_points = 0;             // smallest primitive; <= 0: max(10, N / 500)
  unsigned seed = 1;              // the result is a function of the seed only
  int num_threads = 0;            // 0: hardware concurrency
  int patch_size = 48;            // points of a seed's local patch
  int hypotheses = 24;            // minimal-sample hypotheses per kind per seed
  int seeds_per_round = 16;       // seeds evaluated in parallel per round (fixed: determinism)
  bool refine = true;             // final maximum-likelihood refinement (Ceres)
  // Progress: told a line at each stage and every few seconds of the seed rounds (the `detect`
  // command prints it on stderr); empty: nothing. Called on the detecting thread.
  std::function<void(const std::string&)> progress;

  bool IsValid(std::string* error) const;
};

struct DetectedPrimitive {
  NodeType kind = NodeType::kPlane;
  std::vector<double> parameters;           // flat layout of the kind's evaluator
  std::vector<double> standard_deviations;  // same layout; empty when not computed
  std::vector<int> points;                  // indices into the cloud, ascending
  double rms_distance = 0.0;
  // "outward": the cloud's normals agree with grad f on >= 90% of the points, "inward": they
  // oppose it on >= 90%, else "unknown". Planes are oriented so that they are "outward".
  std::string normal_side = "unknown";
};

struct DetectionResult {
  std::vector<DetectedPrimitive> primitives;  // largest first
  std::vector<int> labels;                    // per point: index into primitives, -1 none
  std::vector<double> residuals;              // per point: f of its primitive (0 when none)
  double spacing = 0.0, noise = 0.0, threshold = 0.0, normal_angle_deg = 0.0;
  int min_points = 0;
  int seeds = 0, candidates_accepted = 0, merges = 0, simplified = 0, splits = 0;
  double seconds = 0.0;
};

// points and normals (one oriented unit normal per point); neighbours: each point's nearest
// neighbours (itself excluded, e.g. datasets/normals/neighbourhoods.h); spacing: the sampling spacing s.
// Throws std::invalid_argument when the sizes disagree or the options are invalid.
DetectionResult DetectPrimitives(const std::vector<Eigen::Vector3d>& points,
                                 const std::vector<Eigen::Vector3d>& normals,
                                 const NeighbourGraph& neighbours, double spacing,
                                 const DetectionOptions& options = {});

}  // namespace implicitfit
