#include "fit/reconstruct/csg_separation.h"

#include <map>
#include <stdexcept>

namespace implicitfit {
namespace {

bool Covers(const CsgTerm& term, std::uint64_t cell) {
  return (cell & term.inside) == term.inside && (cell & term.outside) == 0;
}

}  // namespace

CsgSeparation SeparateCells(const std::vector<CsgSample>& samples, int num_primitives,
                            const CsgSeparationOptions& options) {
  if (num_primitives < 1 || num_primitives > 64)
    throw std::invalid_argument("SeparateCells: between 1 and 64 primitives");
  const std::uint64_t all = num_primitives == 64 ? ~0ULL : (1ULL << num_primitives) - 1;
  std::map<std::uint64_t, std::pair<int, int>> votes;  // cell -> (inside, outside)
  std::map<std::uint64_t, bool> certain;               // cells with a certain outside sample
  for (const CsgSample& s : samples) {
    auto& v = votes[s.signs & all];
    (s.inside ? v.first : v.second) += 1;
    if (s.certain && !s.inside) certain[s.signs & all] = true;
  }
  std::vector<int> order = options.drop_order;
  if (order.empty())
    for (int k = 0; k < num_primitives; ++k) order.push_back(k);
  for (int k : order)
    if (k < 0 || k >= num_primitives)
      throw std::invalid_argument("SeparateCells: drop_order names a literal out of range");
  CsgSeparation result;
  std::vector<std::uint64_t> inside_cells, outside_cells;
  for (const auto& [cell, v] : votes) {
    const bool forced = certain.count(cell) > 0;
    if (!forced && (v.first + v.second < options.min_cell_samples || v.first == v.second)) {
      ++result.unknown_cells;
      continue;
    }
    const bool inside = !forced && v.first > v.second;
    result.conflicting_samples += inside ? v.second : v.first;
    (inside ? inside_cells : outside_cells).push_back(cell);
  }
  result.inside_cells = static_cast<int>(inside_cells.size());
  result.outside_cells = static_cast<int>(outside_cells.size());

  // 1. Full terms, then drop literals that no outside cell needs.
  std::vector<CsgTerm> terms;
  for (std::uint64_t cell : inside_cells) {
    CsgTerm t{cell, ~cell & all};
    const int n_order = static_cast<int>(order.size());
    for (int step = 0; step < 2 * n_order; ++step) {
      // Negative literals first: positive ones bound the term, negative ones only carve it.
      const int k = order[step % n_order];
      const std::uint64_t bit = 1ULL << k;
      if ((step < n_order) != ((t.outside & bit) != 0)) continue;
      CsgTerm wider = t;
      wider.inside &= ~bit;
      wider.outside &= ~bit;
      bool hits_outside = false;
      for (std::uint64_t out : outside_cells) hits_outside = hits_outside || Covers(wider, out);
      if (!hits_outside && options.bounded && (t.inside & bit) && !options.bounded(wider.inside))
        hits_outside = true;  // would open the term
      if (!hits_outside) t = wider;
    }
    if (options.bounded && !options.bounded(t.inside)) ++result.unbounded_terms;
    bool duplicate = false;
    for (const CsgTerm& u : terms)
      duplicate = duplicate || (u.inside == t.inside && u.outside == t.outside);
    if (!duplicate) terms.push_back(t);
  }
  // 2. Drop terms whose inside cells the others cover (last first: earlier terms are kept).
  for (int i = static_cast<int>(terms.size()) - 1; i >= 0 && terms.size() > 1; --i) {
    bool needed = false;
    for (std::uint64_t cell : inside_cells) {
      if (!Covers(terms[i], cell)) continue;
      bool other = false;
      for (int j = 0; j < static_cast<int>(terms.size()); ++j)
        other = other || (j != i && Covers(terms[j], cell));
      needed = needed || !other;
    }
    if (!needed) terms.erase(terms.begin() + i);
  }
  result.terms = terms;
  return result;
}

std::string CsgExpressionText(const std::vector<CsgTerm>& terms,
                              const std::vector<std::string>& names) {
  std::string text;
  for (size_t t = 0; t < terms.size(); ++t) {
    if (t) text += " | ";
    text += "(";
    bool first = true;
    for (size_t k = 0; k < names.size(); ++k) {
      const std::uint64_t bit = 1ULL << k;
      if (!(terms[t].inside & bit) && !(terms[t].outside & bit)) continue;
      if (!first) text += " & ";
      first = false;
      text += (terms[t].outside & bit ? "!" : "") + names[k];
    }
    text += ")";
  }
  return text;
}

}  // namespace implicitfit
