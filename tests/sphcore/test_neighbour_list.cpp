// The Verlet list (CandidateList) and the pairs filtered from it
// (neighbour_list.hpp) against brute force, after the particles have moved.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <set>
#include <utility>
#include <vector>

#include "listed_pairs.hpp"
#include "sphcore/cell_grid.hpp"
#include "sphcore/kernel.hpp"
#include "sphcore/neighbour_list.hpp"
#include "sphcore/permutation.hpp"

namespace {

using sph::Vec2;

using cosph::testing::Pairs;

// A jittered lattice at spacing dx, h = 1.3 dx as the solvers use.
std::vector<Vec2> jittered_lattice(double dx, std::mt19937& random) {
  std::uniform_real_distribution<double> jitter(-0.3 * dx, 0.3 * dx);
  std::vector<Vec2> x;
  for (int a = 0; a < 40; ++a)
    for (int b = 0; b < 30; ++b) x.emplace_back(a * dx + jitter(random), b * dx + jitter(random));
  return x;
}

// A jittered lattice sorted into the order of `grid`, built for `range`, as a
// solver sorts its particles before it lists neighbours.
std::vector<Vec2> sorted_lattice(double dx, std::mt19937& random, sph::CellGrid& grid,
                                 double range) {
  std::vector<Vec2> x = jittered_lattice(dx, random);
  grid.build(x, range, 2);
  sph::permute(grid.order(), x);
  return x;
}

// Moves every particle by exactly `distance` in a random direction.
void move_each_by(std::vector<Vec2>& x, double distance, std::mt19937& random) {
  std::uniform_real_distribution<double> angle(0.0, 2.0 * std::numbers::pi);
  for (Vec2& p : x) {
    const double phi = angle(random);
    p += distance * Vec2(std::cos(phi), std::sin(phi));
  }
}

// The pairs (i, j), j != i, with r_ij < range among the wanted i.
template <class Wanted>
Pairs brute_force(const std::vector<Vec2>& x, double range, Wanted wanted) {
  Pairs pairs;
  for (std::size_t i = 0; i < x.size(); ++i)
    for (std::size_t j = 0; j < x.size(); ++j)
      if (i != j && wanted(long(i)) && (x[i] - x[j]).norm() < range) pairs.emplace(int(i), int(j));
  return pairs;
}

TEST(CandidateList, ListsEveryParticleWithinRange) {
  std::mt19937 random(3);
  const double dx = 0.01, h = 1.3 * dx, range = 2.0 * h + 0.25 * h;
  sph::CellGrid grid;
  std::vector<Vec2> x = sorted_lattice(dx, random, grid, range);
  auto wanted = [](long i) { return i % 4 != 1; };
  sph::CandidateList list;
  list.build(grid, x, range, wanted);
  Pairs found;
  for (long i = 0; i < long(x.size()); ++i)
    for (const int j : list.candidates(i)) EXPECT_TRUE(found.emplace(int(i), j).second);
  EXPECT_EQ(found, brute_force(x, range, wanted));
}

// Particles moved by just under half the skin: the pairs filtered from the
// old Verlet list are exactly the pairs within 2h now, with the kernel's
// gradient factor, the same as a fresh grid search finds.
TEST(NeighbourList, FromAVerletListMatchesBruteForceAfterAMove) {
  std::mt19937 random(5);
  const double dx = 0.01, h = 1.3 * dx, skin = sph::kSkinOverH * h, range = 2.0 * h + skin;
  sph::CellGrid grid;
  std::vector<Vec2> x = sorted_lattice(dx, random, grid, range);
  auto wanted = [](long i) { return i % 5 != 2; };
  sph::CandidateList candidates;
  candidates.build(grid, x, range, wanted);
  const Pairs before = brute_force(x, sph::kernel::kSupport * h, wanted);

  move_each_by(x, sph::verlet_rebuild_distance(h), random);
  sph::NeighbourList list;
  list.build(candidates, x, h);
  const Pairs found = cosph::testing::listed_pairs(list, x, h);
  const Pairs expected = brute_force(x, sph::kernel::kSupport * h, wanted);
  EXPECT_EQ(found, expected);
  // Not vacuous: the move changed which pairs are within 2h.
  EXPECT_NE(expected, before);
  EXPECT_GT(expected.size(), 10000u);
  // The distances it keeps are the bits a pass would get from x_ij.norm():
  // reading them in place of the square root leaves the results unchanged.
  std::size_t checked = 0;
  for (long i = 0; i < static_cast<long>(x.size()); ++i) {
    const auto neighbours = list.neighbours(i);
    const auto r = list.distances(i);
    ASSERT_EQ(r.size(), neighbours.size());
    for (std::size_t k = 0; k < neighbours.size(); ++k, ++checked)
      ASSERT_EQ(r[k], (x[i] - x[neighbours[k]]).norm()) << i << " " << neighbours[k];
  }
  EXPECT_EQ(checked, expected.size());
}

}  // namespace
