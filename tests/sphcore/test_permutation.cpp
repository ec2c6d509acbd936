// Reordering and thinning struct-of-arrays fields: every field moves alike.
#include <gtest/gtest.h>

#include <vector>

#include "sphcore/permutation.hpp"
#include "sphcore/types.hpp"

namespace {

using sph::Vec2;

TEST(Permutation, PermuteMovesEveryFieldAlike) {
  std::vector<int> id{10, 11, 12, 13};
  std::vector<Vec2> x{{0, 0}, {1, 0}, {2, 0}, {3, 0}};
  sph::permute({2, 0, 3, 1}, id, x);
  EXPECT_EQ(id, (std::vector<int>{12, 10, 13, 11}));
  for (std::size_t k = 0; k < id.size(); ++k) EXPECT_EQ(x[k].x(), id[k] - 10);
}

TEST(Permutation, AShorterOrderDropsTheOthersAndKeepsTheOrder) {
  std::vector<int> id{10, 11, 12, 13, 14};
  std::vector<Vec2> x{{0, 0}, {1, 0}, {2, 0}, {3, 0}, {4, 0}};
  std::vector<unsigned char> flag{0, 1, 0, 1, 0};
  sph::permute({0, 2, 4}, id, x, flag);
  EXPECT_EQ(id, (std::vector<int>{10, 12, 14}));
  ASSERT_EQ(x.size(), 3u);
  for (std::size_t k = 0; k < id.size(); ++k) EXPECT_EQ(x[k].x(), id[k] - 10);
  EXPECT_EQ(flag, (std::vector<unsigned char>(3, 0)));
}

}  // namespace
