// Removing the pieces of a solid that no scan point supports (fit/reconstruct/solid_components.h),
// when that can be done soundly: `reconstruct`'s last step, after a verification
// (fit/reconstruct/solid_verification.h) that failed only because of such pieces.
// A piece lies in cells of the arrangement of the tree's literals (its leaves). The cell of
// its witness w (a grid node inside it) is the intersection, over the named leaves L, of L where
// f_L(w) < 0 and of complement(L) where f_L(w) > 0. An unsupported cavity is filled:
// f <- union(f, cell); an unsupported solid piece is cut away: f <- difference(f, cell) (both
// sharp). A cell may reach beyond its piece (elsewhere in space with the same sign vector), so
// nothing is assumed: the model is verified again after each round (at most max_rounds), and
// the repair is kept only when the result verifies; otherwise the model is left as it was.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "fit/reconstruct/solid_verification.h"
#include "model/model.h"

namespace implicitfit {

struct PieceRepair {
  bool verified = false;  // the repaired model verifies (and replaced the input)
  int rounds = 0, filled = 0, removed = 0;
  std::string expression;  // the added terms, e.g. " | (p3 & !p7 & p9)" (empty when none)
  std::string message;     // the last verification's message when the repair did not verify
};

// model and verification: the failed verification of model; replaced by the repaired model and
// its verification when the repair verifies.
PieceRepair RepairUnsupportedPieces(Model* model, SolidVerification* verification,
                                    const std::vector<Eigen::Vector3d>& points,
                                    const std::vector<Eigen::Vector3d>& normals,
                                    const SolidVerificationOptions& options, int max_rounds = 3);

}  // namespace implicitfit
