#include "model/blends/convex_smooth_ops.h"

#include <array>
#include <memory>

namespace implicitfit {

IntegratedUnitStep::IntegratedUnitStep(int order) : order_(order) {
  if (order == 0) return;
  const UnitStep& step = UnitStep::OfOrder(order);
  long double area = 0.0L;
  for (int j = 0; j < order; ++j) {
    const std::vector<double>& p = step.piece(j);
    std::vector<double> q(p.size() + 1, 0.0);
    long double whole = 0.0L;
    for (size_t i = 0; i < p.size(); ++i) {
      q[i + 1] = p[i] / double(i + 1);
      whole += static_cast<long double>(p[i]) / (i + 1);
    }
    pieces_.push_back(q);
    areas_.push_back(static_cast<double>(area));
    area += whole;
  }
}

const IntegratedUnitStep& IntegratedUnitStep::OfOrder(int order) {
  UnitStep::OfOrder(order);  // validates the order (throws std::invalid_argument)
  static const std::array<std::unique_ptr<IntegratedUnitStep>, UnitStep::kMaxOrder + 1> table = [] {
    std::array<std::unique_ptr<IntegratedUnitStep>, UnitStep::kMaxOrder + 1> t;
    for (int n = 0; n <= UnitStep::kMaxOrder; ++n) t[n].reset(new IntegratedUnitStep(n));
    return t;
  }();
  return *table[order];
}

}  // namespace implicitfit
