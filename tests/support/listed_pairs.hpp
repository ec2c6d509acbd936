// The pairs a NeighbourList holds, each checked to carry the kernel's gradient
// factor: shared by the neighbour-list tests of test_cell_grid.cpp and
// test_neighbour_list.cpp.
#pragma once

#include <gtest/gtest.h>

#include <set>
#include <span>
#include <utility>

#include "sphcore/kernel.hpp"
#include "sphcore/neighbour_list.hpp"

namespace cosph::testing {

using Pairs = std::set<std::pair<int, int>>;

// Every listed (i, j) once, with F_ij = (dW/dr)(r_ij) / r_ij. The tolerance is
// relative to the kernel's scale, not to F: near r = 2h, F ~ (2 - s)^2 and
// round-off in s is amplified, legitimately.
inline Pairs listed_pairs(const sph::NeighbourList& list, std::span<const sph::Vec2> x, double h) {
  const double gradient_scale = sph::kernel::normalisation(h) / (h * h);
  Pairs found;
  for (long i = 0; i < static_cast<long>(x.size()); ++i) {
    const auto neighbours = list.neighbours(i);
    const auto F = list.gradient_factors(i);
    EXPECT_EQ(neighbours.size(), F.size());
    for (std::size_t k = 0; k < neighbours.size() && k < F.size(); ++k) {
      const int j = neighbours[k];
      EXPECT_TRUE(found.emplace(static_cast<int>(i), j).second) << "(" << i << ", " << j << ")";
      const double r = (x[i] - x[j]).norm();
      EXPECT_NEAR(F[k], sph::kernel::dW_dr(r, h) / r, 1e-12 * gradient_scale);
    }
  }
  return found;
}

}  // namespace cosph::testing
