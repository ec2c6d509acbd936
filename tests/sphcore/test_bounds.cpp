// sph::bounds_of, the interaction bounds a solver sends every coupled step:
// the box of the positions asked for, as Region::include finds it one position
// at a time, whichever lane of its vectorised pass the extremes fall in.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "sphcore/region.hpp"

namespace sph {
namespace {

template <class Included>
Region included_one_by_one(const std::vector<Vec2>& x, Included included) {
  Region box;
  for (long i = 0; i < static_cast<long>(x.size()); ++i)
    if (included(i)) box.include(x[i]);
  return box;
}

TEST(Bounds, BoxOfThePositionsAskedFor) {
  for (const long n : {1L, 9L, 37L}) {
    std::vector<Vec2> x;
    for (long i = 0; i < n; ++i) {
      const double t = static_cast<double>(i);
      x.emplace_back(std::sin(1.7 * t), std::cos(0.9 * t) - 0.3 * t);
    }
    const auto every_third = [](long i) { return i % 3 == 1; };
    const auto none = [](long) { return false; };
    const Region all = bounds_of(x), some = bounds_of(x, every_third);
    const Region all_expected = included_one_by_one(x, [](long) { return true; });
    const Region some_expected = included_one_by_one(x, every_third);
    EXPECT_EQ(all.min, all_expected.min) << n;
    EXPECT_EQ(all.max, all_expected.max) << n;
    EXPECT_EQ(some.min, some_expected.min) << n;
    EXPECT_EQ(some.max, some_expected.max) << n;
    EXPECT_TRUE(bounds_of(x, none).empty()) << n;
  }
  EXPECT_TRUE(bounds_of(std::vector<Vec2>{}).empty());
}

}  // namespace
}  // namespace sph
