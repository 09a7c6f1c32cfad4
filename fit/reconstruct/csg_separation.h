// A Boolean expression over primitives from classified sample points (Shapiro & Vossler's
// separation, in the form this project uses it).
//
// Each sample point x has a sign vector: bit k set when f_k(x) < 0 (x inside primitive k). The
// samples split into cells of the arrangement of the primitives; a cell is inside when most of
// its samples are inside the solid, outside when most are outside, and unknown (don't care) when
// it holds fewer than min_cell_samples samples. The solid is then the union, over inside cells,
// of the intersection of the cell's literals (k or not-k for every primitive): a disjunctive
// normal form that is exact on the observed cells. It is simplified like a Boolean function:
//   1. every term drops each literal whose removal keeps the term away from every outside cell
//      (the term then covers more inside or unknown cells only): first the negative literals,
//      then the positive ones, each in index order (positive literals bound a term, negative
//      ones only carve it, so a boss keeps the slab's bottom rather than 'not the slab's top');
//   2. terms whose inside cells are all covered by the other terms are dropped.
// (The order of step 1 can be given: fit/reconstruct/solid_bounding.h's closures and separators first.) A
// cell holding a `certain` outside sample is outside whatever its votes. With a boundedness
// test, step 1 keeps every term bounded (a positive literal stays when dropping it would open
// the term: a term may extend through space no sample covers).
// Outside samples on a shell around the object keep terms bounded (a term that would extend to
// infinity meets them). Why this and not convex decomposition: the primitives of a CAD part are
// not convex (bores, bosses), and separation works on any primitive kind and on concave
// (union) and hole (difference) features alike, from inside/outside samples only.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace implicitfit {

struct CsgSample {
  std::uint64_t signs = 0;  // bit k: inside primitive k
  bool inside = false;      // the sample is inside the solid
  bool certain = false;     // an outside sample that makes its cell outside whatever the votes
                            // (a point outside the closure box: the solid is declared in it)
};

// One term of the union: intersection of the primitives in `inside` minus those in
// `outside` (bit masks over primitives).
struct CsgTerm {
  std::uint64_t inside = 0, outside = 0;
};

struct CsgSeparationOptions {
  int min_cell_samples = 3;  // cells with fewer samples are "don't care"
  // The order in which literals are tried for dropping (empty: 0, 1, ...); literals tried
  // first are dropped whenever possible (closures and separators before detected surfaces).
  std::vector<int> drop_order;
  // When set: whether the intersection of the literals in a mask is bounded
  // (fit/reconstruct/term_bounds.h). A positive literal is then dropped only when the term stays
  // bounded; terms that are unbounded from the start (a cell no literal closes) are counted.
  std::function<bool(std::uint64_t)> bounded;
};

struct CsgSeparation {
  std::vector<CsgTerm> terms;
  int inside_cells = 0, outside_cells = 0, unknown_cells = 0;
  int conflicting_samples = 0;  // samples whose cell's majority disagrees with them
  int unbounded_terms = 0;      // terms that options.bounded calls unbounded (none without it)
};

// num_primitives <= 64.
CsgSeparation SeparateCells(const std::vector<CsgSample>& samples, int num_primitives,
                            const CsgSeparationOptions& options = {});

// "(p0 & p1 & !p2) | (p3)" with the given primitive names.
std::string CsgExpressionText(const std::vector<CsgTerm>& terms,
                              const std::vector<std::string>& names);

}  // namespace implicitfit
