// The median of a list of numbers, by selection (std::nth_element, O(n)): the element of rank
// n/2 (0-based), i.e. the upper median when n is even; 0 for an empty list. The fitters' robust
// noise scale is sigma = 1.4826 Median(|r_i|) (the MAD of a normal distribution).
#pragma once

#include <algorithm>
#include <vector>

namespace implicitfit {

inline double Median(std::vector<double> values) {
  if (values.empty()) return 0.0;
  const auto middle = values.begin() + values.size() / 2;
  std::nth_element(values.begin(), middle, values.end());
  return *middle;
}

}  // namespace implicitfit
