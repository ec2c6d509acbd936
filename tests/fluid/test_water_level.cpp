// The water-level gauge (fluid/src/water_level.hpp): on a lattice of water
// the level is the lattice's top edge, half a spacing above the top row, to
// a small fraction of a spacing; a probe with no water near reads nothing.
#include <gtest/gtest.h>

#include "fluid_particles.hpp"
#include "water_level.hpp"

namespace cosph::fluid {
namespace {

constexpr double kDx = 0.01, kH = 1.3 * kDx, kRho0 = 1000.0;

// Water on the lattice of spacing dx over 0 < x < 0.4: 0.1 m deep left of
// x = 0.2, 0.05 m deep right of it.
FluidParticles stepped_water() {
  FluidParticles P;
  int id = 0;
  for (int i = 0; i < 40; ++i) {
    const double x = (i + 0.5) * kDx, depth = x < 0.2 ? 0.1 : 0.05;
    for (double y = 0.5 * kDx; y < depth; y += kDx)
      P.add(id++, Kind::water, Vec2(x, y), kRho0, kRho0 * kDx * kDx);
  }
  P.resize_derived();
  return P;
}

TEST(WaterLevel, ReadsTheTopEdgeOfALattice) {
  const FluidParticles P = stepped_water();
  // Between lattice columns and on them, away from the step by more than 2h.
  for (double x : {0.07, 0.075, 0.123}) {
    const auto level = water_level(P, x, kH, kDx);
    ASSERT_TRUE(level.has_value());
    EXPECT_NEAR(*level, 0.1, 0.03 * kDx) << "x = " << x;
  }
  for (double x : {0.3, 0.335}) {
    const auto level = water_level(P, x, kH, kDx);
    ASSERT_TRUE(level.has_value());
    EXPECT_NEAR(*level, 0.05, 0.03 * kDx) << "x = " << x;
  }
  EXPECT_FALSE(water_level(P, 0.5, kH, kDx).has_value());
}

TEST(WaterLevel, FollowsTheSurfaceWhenItRises) {
  // Lifting the water by a third of a spacing lifts the level by as much.
  FluidParticles P = stepped_water();
  const double before = *water_level(P, 0.1, kH, kDx);
  for (Vec2& x : P.x) x.y() += kDx / 3;
  EXPECT_NEAR(*water_level(P, 0.1, kH, kDx) - before, kDx / 3, 1e-9);
}

}  // namespace
}  // namespace cosph::fluid
