// A solid model of a scan from its detected primitives (`implicitfit reconstruct`):
//   1. points are assigned to the primitive they fit (|f_k| / |grad f_k| < tau_k, tau_k = max(3
//      rms_k, 1e-3 diag), |cos(grad f_k, n)| >= 0.8; the smallest distance in units of tau_k);
//   2. orientation: a primitive is material-inside when most of its points' normals agree in
//      sign with grad f_k, a hole otherwise (a bore: the cylinder is subtracted); planes are
//      flipped so that f < 0 is their material side. When at least resign_majority of a
//      primitive's points agree, the others' normals are re-signed to that side (one smooth
//      sheet has one outward side; a points-only L-bracket's bore of radius 0.18 through a
//      0.3 wall had 83 of its 283 estimated normals inverted over its lower half), and every
//      later step, the verification included, uses the re-signed normals;
//   3. the Boolean expression: samples p -+ t n (t = 1% of the diagonal, shortened to half the
//      distance to the next surface along the normal: fit/reconstruct/offset_samples.h) of the assigned
//      points are inside / outside, points on a box 10% larger than the cloud's are outside;
//      fit/reconstruct/csg_separation.h turns them into a union of terms, each term
//      difference(intersection(positive literals), negative literals) (no complement node needed:
//      every bounded term has a positive literal). While a cell of the arrangement holds many
//      inside and many outside samples, a separating plane is added (fit/reconstruct/solid_bounding.h); when
//      the solid is still unbounded (an open scan), the closure box's faces are added and the
//      solid declared inside it; the closure faces used are reported as not measured; a fillet
//      (a torus, hole or solid) adds the planes and coaxial cylinders that bound its points
//      (fit/reconstruct/fillet_separators.h);
//   4. blends: an operator is made smooth (Li & Phillips, order 3) when enough points fit
//      neither primitive but lie in its crease region: the two most active children w_a, w_b
//      (subtrahends negated) are in [-R, tau] (R = max_fillet of the diagonal) and the normal
//      has a positive component along both gradients. delta starts at the median of
//      (sqrt(-w_a) + sqrt(-w_b))^2, which solves the blend's zero set a + b + (a - b)^2 / (2
//      delta) + delta / 2 = 0 in its parabolic zone; epsilon at 0.6 delta. Other operators are
//      sharp (order 0, delta and epsilon fixed);
//   5. every free parameter is refined with the tree fitter (fit/tree/tree_fitter.h) on the points
//      within R of the initial model; standard deviations from fit/tree/tree_covariance.h. Only the
//      smooth operators and the primitives below them are free: a primitive under sharp
//      operators only keeps the primitive fitter's parameters (a point's residual there depends
//      on that primitive alone, which was fitted to its own points), and a tree without a blend
//      is not refitted (the fit over a whole tree of 18 primitives took hours on Fit4CAD PC131).
//   6. verification (fit/reconstruct/solid_verification.h): bounded (proven), inside/outside
//      agrees with the oriented cloud, every piece and cavity supported by scan points; success
//      only when it passes. The model's leaves carry the primitives' names (so the expression
//      maps to the model) and its claims (ModelClaims) the proven bounds and the verdict. When
//      only unsupported pieces fail it, each is filled (a cavity) or cut away (a solid piece) by
//      its cell of the arrangement, and the result verified again
//      (fit/reconstruct/unsupported_repair.h); kept only when it verifies.
// Progress (options.progress, fit/common/progress.h): stages "orientation" (steps 1-2),
// "separation" (3), "blends" (4), "tree fit" (5), "verification" (6).
// The implied fillet radius of a blend: on the bisector of two faces whose outward normals make
// the angle phi, the blended zero set sits at distance delta / 4 from both faces (a = b:
// 2a + delta / 2 = 0); a circular fillet of radius rho tangent to both has its arc there when
// rho = delta / (4 (1 - cos(phi / 2))) (phi = 90 deg: rho = 0.854 delta).
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "fit/common/progress.h"
#include "fit/reconstruct/point_assignment.h"
#include "fit/reconstruct/solid_verification.h"
#include "fit/tree/tree_fitter.h"
#include "model/model.h"

namespace implicitfit {

struct SolidPrimitive {
  std::string name;  // "p0", ...
  Model model;       // the primitive as a model (usually one node)
  double rms = 0.0;  // RMS distance of its points, 0 when unknown
};

struct SolidReconstructionOptions {
  double max_fillet = 0.1;  // R: largest fillet considered, fraction of the diagonal
  double offset = 0.01;     // t of the inside/outside samples, fraction of the diagonal
  // Shorten t where another surface lies within t along the normal (fit/reconstruct/offset_samples.h).
  bool adaptive_offset = true;
  // A torus (a hole: concave fillet; solid: convex fillet) brings the box of revolution of its
  // points as separators (fit/reconstruct/fillet_separators.h).
  bool fillet_separators = true;
  // Drop the primitives whose points lie on larger ones (crease bands that detect fitted with
  // extra surfaces: fit/reconstruct/point_assignment.h): share of their points within
  // max(2.5 rms, redundant_floor of the diagonal) of the larger primitives.
  bool drop_redundant = true;
  double redundant_share = 0.8;
  double redundant_floor = 1e-4;
  int min_transition_points = 20;          // a blend needs at least this many transition points
  double min_transition_fraction = 0.003;  // ... and this fraction of the cloud
  int blend_order = 3;
  int max_samples = 20000;  // inside/outside samples drawn from the assigned points
  // The joint refinement (step 5) runs on at most this many points near the solid: every
  // unassigned one and a random subset of the assigned ones.
  int max_fit_points = 4000;
  // Separators (fit/reconstruct/solid_bounding.h): a cell is mixed when its minority has at least
  // max(min_conflict_samples, min_conflict_fraction of all samples) and 10% of its samples.
  int max_separators = 16;
  int min_conflict_samples = 20;
  double min_conflict_fraction = 0.005;
  double closure_margin = 0.02;  // closure box: the assigned points' box + this of the diagonal
  // Step 2: a primitive's points whose normals face the minority side are re-signed when at
  // least this share of them face the majority side.
  double resign_majority = 0.6;
  // Per primitive (empty: none): its points are a rounding of the faces it joins, modelled by
  // a blend of their intersection (step 4), not a literal of its own; side "blend".
  std::vector<bool> as_blends;
  // When the solid does not verify, a second attempt with the fillet-like primitives
  // (fit/reconstruct/fillet_primitives.h) as blends; taken when it verifies.
  bool fillets_as_blends = true;
  unsigned seed = 1;
  TreeFitOptions tree;
  SolidVerificationOptions verification;  // step 6
  ProgressCallback progress;              // stages, fit/common/progress.h (empty: silent)
};

struct BlendEstimate {
  std::string node;  // the operator's label in the model
  std::string type;  // union, intersection, difference
  int transition_points = 0;
  double delta = 0, epsilon = 0, sd_delta = 0, sd_epsilon = 0;
  double crease_angle_deg = 0;  // phi, median over the transition points
  double fillet_radius = 0, sd_fillet_radius = 0;
};

// A plane the reconstruction added that is not a detected surface: f = normal . x - offset.
struct AddedPlane {
  std::string name;  // "separator0", "closure2", ... as in the expression and the model
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();
  double offset = 0.0;
};

// A coaxial cylinder the reconstruction added as a separator (a concave fillet's bound,
// fit/reconstruct/fillet_separators.h): f = |(x - point) x axis| - radius.
struct AddedCylinder {
  std::string name;  // "separator_cylinder0", ...
  Eigen::Vector3d point = Eigen::Vector3d::Zero(), axis = Eigen::Vector3d::UnitZ();
  double radius = 0.0;
};

struct SolidReconstruction {
  bool success = false;
  std::string message;
  Model model;                     // the fitted solid
  std::string expression;          // e.g. "(p0 & p1 & !p2) | (p3)"
  // per primitive: "solid", "hole", "unused" or "blend" (SolidReconstructionOptions::as_blends)
  std::vector<std::string> sides;
  std::vector<int> assigned;       // points per primitive
  PointAssignment assignment;      // step 1, on the primitives as given
  // The primitives of the second attempt's blends (SolidReconstructionOptions::fillets_as_blends)
  // when it was taken; empty otherwise.
  std::vector<std::string> fillets_as_blends;
  int unassigned = 0;
  int resigned_normals = 0;  // step 2: normals re-signed to their primitive's majority side
  bool bounded = false;  // proven by the verification (f > 0 outside verification's bounds)
  double rms = 0.0;      // RMS first-order distance of the fit's inliers
  double sigma = 0.0;
  int inliers = 0;
  double normal_agreement = 0.0;      // share of inliers with n . grad f > 0
  std::vector<BlendEstimate> blends;  // smooth operators only
  // Planes in the expression that no data lie on: separators split cells of the arrangement;
  // closures close the solid where the scan has no data (their faces are not measured).
  std::vector<AddedPlane> separators, closures;
  std::vector<AddedCylinder> separator_cylinders;
  SolidVerification verification;  // step 6; success = verification.verified
  // Unsupported pieces repaired (fit/reconstruct/unsupported_repair.h; the expression shows the
  // added terms): cavities filled, solid pieces cut away.
  int filled_cavities = 0, removed_pieces = 0;
  // Separators replaced by measured planes to join pieces (fit/reconstruct/separator_bridging.h),
  // e.g. "separator2 -> p0"; empty when none.
  std::string bridged_separators;
  double seconds = 0.0;
  double fit_seconds = 0.0;  // of which the joint refinement (step 5)
  int fit_iterations = 0;
};

SolidReconstruction ReconstructSolid(const std::vector<Eigen::Vector3d>& points,
                                     const std::vector<Eigen::Vector3d>& normals,
                                     const std::vector<SolidPrimitive>& primitives,
                                     const SolidReconstructionOptions& options = {});

// Primitives from labelled points (labels[i] = k: point i lies on primitive k, -1: none), each
// fitted with the primitive fitter (fit/primitive/primitive_fitter.h) as kinds[k]: the scene that `detect`
// would give, e.g. from ground-truth labels. Throws std::runtime_error naming a failed primitive.
std::vector<SolidPrimitive> FitLabelledPrimitives(const std::vector<Eigen::Vector3d>& points,
                                                  const std::vector<Eigen::Vector3d>& normals,
                                                  const std::vector<int>& labels,
                                                  const std::vector<NodeType>& kinds,
                                                  unsigned seed);

// The fillet radius of the header for a blend of parameter delta at a crease of angle phi.
double ImpliedFilletRadius(double delta, double crease_angle_rad);

}  // namespace implicitfit
