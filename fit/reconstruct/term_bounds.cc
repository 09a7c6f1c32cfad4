#include "fit/reconstruct/term_bounds.h"

#include "fit/reconstruct/blend_refit.h"
#include "fit/reconstruct/polytope_box.h"
#include "fit/reconstruct/sublevel_enclosure.h"

namespace implicitfit {

bool TermIsBounded(const std::vector<Model>& literals, std::uint64_t positives,
                   const Eigen::Vector3d& limit_lo, const Eigen::Vector3d& limit_hi) {
  Model term;
  std::vector<int> children;
  for (size_t k = 0; k < literals.size() && k < 64; ++k)
    if (positives >> k & 1)
      children.push_back(CopySubtree(literals[k], literals[k].root(), &term));
  if (children.empty()) return false;  // all of space
  if (children.size() > 1)
    term.SetRoot(term.AddOperator(NodeType::kIntersection, children, 0.0, 0.0, 0));
  else
    term.SetRoot(children[0]);
  const SublevelEnclosure enclosure = EncloseSublevel(term);
  if (enclosure.overflow) return false;
  for (const EnclosurePiece& piece : enclosure.pieces) {
    if (!piece.outside.empty()) return false;  // not made of faces (no positive literal is)
    const PolytopeExtent extent = BoundPolytope(piece.faces, limit_lo, limit_hi).extent;
    if (extent != PolytopeExtent::kEmpty && extent != PolytopeExtent::kBounded) return false;
  }
  return true;
}

}  // namespace implicitfit
