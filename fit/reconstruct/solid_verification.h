// Does a model describe a solid the scan supports? `reconstruct` (and `batch --model solid`)
// run this before they call a result a success, `verify` runs it on any model and cloud
// (docs/reconstruct.md). Options and result in the style of ceres::Solver::Options / Summary.
// Three checks, each reported with how it was done:
//   1. bounded, proven: {f <= 0} is enclosed in a union of convex polyhedra built from the
//      tree's structure (fit/reconstruct/sublevel_enclosure.h), and every polyhedron is shown
//      empty or bounded within the cloud's box grown by max_reach diagonals by exact linear
//      programming (fit/reconstruct/polytope_box.h); the union of their boxes is the solid's
//      bounds (f > 0 outside it). A polyhedron that leaves that box is split on its deferred
//      outside-of-a-convex-primitive literals (SplitOnOutside) and its parts are decided in
//      turn (at most max_decided_pieces). One that still leaves the box fails the check; its
//      deepest point beyond the limit is reported with f there (f <= 0: the solid truly
//      reaches out that way, e.g. an infinite cylinder; f > 0: the enclosure is too coarse,
//      not proven). As a consistency test of the proof, f is also sampled on the faces of the
//      bounds grown by 1% (33 x 33 per face): a value <= 0 there fails the check.
//   2. inside/outside agrees with the data: for each scan point p with oriented normal n and
//      first-order distance d = f / |grad f|, the samples p - t n must have f < 0 and p + t n
//      f > 0, t = |d| + max(3 sigma, 1e-3 diagonal), sigma = 1.4826 median |d| (the data's
//      noise about the model). Points farther than max_offset (of the diagonal) from the
//      surface are not explained by the model: they count in `explained`, not in the
//      agreement. Agreement over the explained points >= min_agreement, and for each primitive
//      (the leaf of the tree with the smallest |f| at the point; a primitive's f is a distance,
//      exact or first-order) with at least
//      min_primitive_points points >= min_primitive_agreement; explained share >=
//      min_explained.
//   3. no unsupported pieces: the grid of `mesh`'s default for these bounds (the bounds grown
//      by 10%, cell = longest side / grid_cells, two more cells on every side) is split into
//      solid components and enclosed cavities, and each must carry scan points on its boundary
//      (fit/reconstruct/solid_components.h). An unsupported piece fails the check (its
//      witness, a grid node inside it, is reported).
// verified = all three pass. A model that is not bounded still gets checks 2 and 3 (3 on the
// cloud's box grown by 10%), so the report says everything that is wrong.
#pragma once

#include <Eigen/Core>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "fit/common/progress.h"
#include "fit/reconstruct/solid_components.h"
#include "model/model.h"

namespace implicitfit {

struct SolidVerificationOptions {
  // 1. bounded
  int max_enclosure_pieces = 512;
  // Polyhedra decided by linear programming at most, splits on outside literals included.
  int max_decided_pieces = 4096;
  // Every polyhedron must lie within the cloud's box grown by this (of its diagonal): rounded
  // half-spaces can close an open tube ~1e17 away (fit/reconstruct/polytope_box.h), and a solid
  // reaching that far from its scan is not supported by it.
  double max_reach = 1.0;
  // 2. inside/outside
  double max_offset = 0.01;  // of the cloud's diagonal: farther points are unexplained
  double min_agreement = 0.9;
  double min_primitive_agreement = 0.7;
  int min_primitive_points = 20;
  double min_explained = 0.5;
  // 3. pieces
  int grid_cells = 100;  // cells along the longest side of the bounds grown by 10% (as `mesh`)
  SolidComponentOptions components;
  int num_threads = 0;  // 0: every core
  ProgressCallback progress;
};

struct PrimitiveAgreement {
  std::string name;  // the leaf's "name" (or its path in the tree)
  int points = 0;    // explained points nearest to it
  double agreement = 0.0;
  bool checked = false;  // points >= min_primitive_points
  bool passed = true;
};

struct SolidVerification {
  bool verified = false;
  std::string message;                // "verified", or the failed checks' reasons
  std::vector<std::string> failures;  // one reason per failed check

  // 1. bounded
  bool bounded = false;
  int enclosure_pieces = 0, bounded_pieces = 0, empty_pieces = 0;
  int decided_pieces = 0, split_pieces = 0;  // LP-decided; split on an outside literal
  bool enclosure_overflow = false;
  Eigen::Vector3d bounds_min = Eigen::Vector3d::Zero(), bounds_max = Eigen::Vector3d::Zero();
  double max_reach = 0.0;            // the option, for the report
  std::string unbounded_piece;       // label of the first unbounded polyhedron
  bool unbounded_infinite = false;   // it is unbounded (not only beyond max_reach)
  std::string unbounded_reason;      // nodes that gave no bound on its way, if any
  Eigen::Vector3d unbounded_direction = Eigen::Vector3d::Zero();
  Eigen::Vector3d unbounded_witness = Eigen::Vector3d::Zero();
  double unbounded_witness_value = 0.0;  // f at the witness
  int face_samples = 0;
  double face_min_value = 0.0;  // min f on the faces of the grown bounds

  // 2. inside/outside
  int points = 0, explained_points = 0, agreeing_points = 0;
  double explained = 0.0, agreement = 0.0;
  double sigma = 0.0;  // 1.4826 median |d|
  std::vector<PrimitiveAgreement> primitives;

  // 3. pieces
  SolidComponents components;
  bool pieces_supported = false;

  double seconds = 0.0;

  // One line: "verified: bounded, agreement 0.998, 1 solid, 0 cavities" or the reasons.
  std::string BriefReport() const;
  // The report's "verification" object (docs/reconstruct.md).
  nlohmann::json ToJson() const;
};

// points/normals: the scan with oriented (outward) unit normals, as the reconstruction used.
SolidVerification VerifySolid(const Model& model, const std::vector<Eigen::Vector3d>& points,
                              const std::vector<Eigen::Vector3d>& normals,
                              const SolidVerificationOptions& options = {});

// The mesh grid `mesh` uses by default for a model with these bounds
// (datasets/meshing/model_mesher.h): the bounds grown by 10% of their size, cell = the longest
// side / cells, two more cells on every side.
void DefaultSolidGrid(const Eigen::Vector3d& bounds_min, const Eigen::Vector3d& bounds_max,
                      int cells, Eigen::Vector3d* lo, Eigen::Vector3d* hi, double* cell);

// The leaves below the root, one (name, node index) per name, in tree order (a literal copied
// into several terms counts once); unnamed leaves are named by their path (Model::NodeLabel).
std::vector<std::pair<std::string, int>> SolidLeaves(const Model& model);

// Writes the verification's claims into the model (ModelClaims: the bounds when proven, and
// verified or not with the reason).
void ClaimVerification(const SolidVerification& v, Model* model);

}  // namespace implicitfit
