// Median (model/median.h) against sorting: the element of rank n/2 of the sorted list.
#include "model/median.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

namespace {

TEST(Median, IsTheElementOfRankHalfNOfTheSortedList) {
  std::mt19937 rng(5);
  std::normal_distribution<double> gauss(0.0, 1.0);
  for (int n = 1; n <= 40; ++n) {
    std::vector<double> v(n);
    for (double& x : v) x = gauss(rng);
    std::vector<double> sorted = v;
    std::sort(sorted.begin(), sorted.end());
    EXPECT_EQ(implicitfit::Median(v), sorted[n / 2]) << n;
  }
  EXPECT_EQ(implicitfit::Median({3.0, 1.0, 2.0}), 2.0);
  EXPECT_EQ(implicitfit::Median({4.0, 1.0}), 4.0);  // upper median for an even count
  EXPECT_EQ(implicitfit::Median({}), 0.0);
}

}  // namespace
