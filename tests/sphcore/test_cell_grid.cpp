// The cell-linked-list neighbour search (cell_grid.hpp) against brute force.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <set>
#include <stdexcept>
#include <utility>
#include <vector>

#include "listed_pairs.hpp"
#include "sphcore/cell_grid.hpp"
#include "sphcore/kernel.hpp"
#include "sphcore/neighbour_list.hpp"
#include "sphcore/permutation.hpp"

namespace {

using sph::CellGrid;
using sph::Vec2;

using cosph::testing::Pairs;

// Every (query q, particle j) with |p_q - x_j| < range, j in the caller's order.
Pairs brute_force(const std::vector<Vec2>& queries, const std::vector<Vec2>& x, double range) {
  Pairs pairs;
  for (std::size_t q = 0; q < queries.size(); ++q)
    for (std::size_t j = 0; j < x.size(); ++j)
      if ((queries[q] - x[j]).norm() < range) pairs.emplace(int(q), int(j));
  return pairs;
}

// The same through the grid: candidates come as ranges of sorted indices k,
// which stand for the caller's particle order()[k].
Pairs through_grid(const std::vector<Vec2>& queries, const std::vector<Vec2>& x, double range) {
  CellGrid grid;
  grid.build(x, range);
  EXPECT_EQ(grid.order().size(), x.size());
  std::vector<int> sorted_order = grid.order();
  std::sort(sorted_order.begin(), sorted_order.end());
  for (std::size_t k = 0; k < sorted_order.size(); ++k)
    EXPECT_EQ(sorted_order[k], int(k)) << "order() is not a permutation";
  Pairs pairs;
  for (std::size_t q = 0; q < queries.size(); ++q)
    grid.for_each_candidate_range(queries[q], [&](int begin, int end) {
      for (int k = begin; k < end; ++k) {
        const int j = grid.order()[k];
        if ((queries[q] - x[j]).norm() < range) {
          const bool fresh = pairs.emplace(int(q), j).second;
          EXPECT_TRUE(fresh) << "particle " << j << " visited twice for query " << q;
        }
      }
    });
  return pairs;
}

// Clusters of particles much denser than the cells, a sparse background, and
// one particle far from everything.
std::vector<Vec2> clustered_cloud(unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::normal_distribution<double> spread(0.0, 0.01);
  std::vector<Vec2> x;
  for (int c = 0; c < 5; ++c) {
    const Vec2 centre(unit(random), unit(random));
    for (int k = 0; k < 200; ++k) x.push_back(centre + Vec2(spread(random), spread(random)));
  }
  for (int k = 0; k < 300; ++k) x.emplace_back(unit(random), unit(random));
  x.emplace_back(7.3, -4.1);  // isolated: no neighbour but itself
  return x;
}

TEST(CellGrid, MatchesBruteForceOnAClusteredCloud) {
  const double range = 0.026;
  for (unsigned seed = 1; seed <= 3; ++seed) {
    const std::vector<Vec2> x = clustered_cloud(seed);
    const Pairs expected = brute_force(x, x, range);
    EXPECT_EQ(through_grid(x, x, range), expected) << "seed " << seed;
    EXPECT_TRUE(expected.count({int(x.size()) - 1, int(x.size()) - 1}));
    EXPECT_GT(expected.size(), 10 * x.size());  // the clusters are really dense
  }
}

TEST(CellGrid, MatchesBruteForceOnALatticeWithPointsOnCellEdges) {
  // Particles exactly on multiples of the cell size, and pairs exactly one
  // range apart (which must not count: r < 2h).
  const double range = 0.25;
  std::vector<Vec2> x;
  for (int i = 0; i <= 12; ++i)
    for (int j = 0; j <= 8; ++j) x.emplace_back(0.125 * i, 0.125 * j);
  EXPECT_EQ(through_grid(x, x, range), brute_force(x, x, range));
}

TEST(CellGrid, QueriesOutsideTheGridSeeOnlyTrueNeighbours) {
  const double range = 0.05;
  std::vector<Vec2> x;
  for (int i = 0; i < 20; ++i)
    for (int j = 0; j < 20; ++j) x.emplace_back(0.02 * i, 0.02 * j);
  const std::vector<Vec2> queries{{-0.03, 0.1}, {0.42, 0.41},  {-0.5, -0.5},
                                  {10.0, 0.1},  {0.2, -0.049}, {0.19, 0.2}};
  EXPECT_EQ(through_grid(queries, x, range), brute_force(queries, x, range));
}

TEST(CellGrid, EmptyAndSingleParticle) {
  CellGrid grid;
  grid.build(std::vector<Vec2>{}, 0.1);
  EXPECT_TRUE(grid.order().empty());
  int visits = 0;
  grid.for_each_candidate_range(Vec2(0.0, 0.0), [&](int, int) { ++visits; });
  EXPECT_EQ(visits, 0);

  const std::vector<Vec2> one{{0.3, -0.2}};
  EXPECT_EQ(through_grid(one, one, 0.1), (Pairs{{0, 0}}));
  EXPECT_EQ(through_grid(std::vector<Vec2>{Vec2(5.0, 5.0)}, one, 0.1), Pairs{});
}

TEST(CellGrid, RefusesParticlesSpreadOverAbsurdlyManyCells) {
  // Two particles a thousand kilometres apart with millimetre cells: a blown-up
  // run. The grid must refuse instead of allocating 10^18 cells.
  CellGrid grid;
  const std::vector<Vec2> x{{0.0, 0.0}, {1e6, 1e6}};
  EXPECT_THROW(grid.build(x, 0.001), std::runtime_error);
  const std::vector<Vec2> not_finite{{0.0, 0.0}, {std::nan(""), 0.0}};
  EXPECT_THROW(grid.build(not_finite, 0.001), std::runtime_error);
}

TEST(NeighbourList, MatchesBruteForceWithKernelFactors) {
  // The list is built on particles already sorted into the grid's order, as a
  // solver does; particles not wanted (here every third) get no neighbours but
  // are still neighbours of others.
  const double h = 0.013;
  std::vector<Vec2> x = clustered_cloud(5);
  CellGrid grid;
  grid.build(x, sph::kernel::kSupport * h);
  sph::permute(grid.order(), x);
  sph::CandidateList candidates;  // within 2h: a Verlet list without a skin
  candidates.build(grid, x, sph::kernel::kSupport * h, [](long i) { return i % 3 != 0; });
  sph::NeighbourList list;
  list.build(candidates, x, h);

  Pairs expected;
  for (const auto& [i, j] : brute_force(x, x, sph::kernel::kSupport * h))
    if (i != j && i % 3 != 0) expected.emplace(i, j);
  EXPECT_EQ(cosph::testing::listed_pairs(list, x, h), expected);
}

}  // namespace
