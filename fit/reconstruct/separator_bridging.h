// Joining the pieces a misplaced separator cut apart (`reconstruct`, after the verification,
// fit/reconstruct/solid_verification.h). A separator (fit/reconstruct/solid_bounding.h) is a plane
// no scan point lies on, placed in the middle of the gap between a cell's inside and outside
// samples; where that gap is a stretch of space the scan does not constrain (Fit4CAD PC155: a
// dome on a slab whose top face is also sampled under the dome), the plane may leave a slot
// between a term and the rest, and the verified solid comes out in two pieces.
// For each separator leaf (a plane named "separator...") of a solid with more than one solid
// piece, its plane is replaced by each measured plane leaf of the model (a primitive, same
// orientation: material where f < 0), one at a time; of the replacements with which the model
// verifies with fewer solid pieces (the verification decides; nothing is assumed about the cell
// the new plane opens), the one with the least solid volume is kept: the join adding the least
// material no scan point asked for (a hand-built dome cut 0.1 above its slab: the slab's side
// plane also joins it but lets the ball's cap hang 0.1 below the slab, which the piece check
// cannot see, the pieces being supported; the bottom plane does not). At most max_trials
// verifications.
#pragma once

#include <Eigen/Core>
#include <string>
#include <utility>
#include <vector>

#include "fit/reconstruct/solid_verification.h"
#include "model/model.h"

namespace implicitfit {

struct SeparatorBridging {
  int trials = 0;
  std::vector<std::pair<std::string, std::string>> replaced;  // (separator, measured plane)
  std::string Text() const;  // "separator2 -> p0, ..." (empty when none)
};

// model and verification: a verified model and its verification; both replaced by the better
// one when a replacement verifies with fewer solid pieces.
SeparatorBridging BridgeSeparatedPieces(Model* model, SolidVerification* verification,
                                        const std::vector<Eigen::Vector3d>& points,
                                        const std::vector<Eigen::Vector3d>& normals,
                                        const SolidVerificationOptions& options,
                                        int max_trials = 24);

// The expression with each whole-word name `from` replaced by `to`.
std::string RenameInExpression(std::string expression, const std::string& from,
                               const std::string& to);

}  // namespace implicitfit
