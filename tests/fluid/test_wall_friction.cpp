// fluid.wall_friction (proto/case.proto): with "dissipation" the momentum
// equation's dissipation term acts between the water and its walls and brakes
// water sliding along a wall; with "none" (free-slip walls) it is left out
// against walls, in the water's accelerations and in the force on the wall
// alike; with "normal" it acts on the approach along the wall's normal only.
#include <gtest/gtest.h>

#include <string>

#include "equation_of_state.hpp"
#include "fluid_dynamics.hpp"
#include "fluid_parameters.hpp"
#include "fluid_test_support.hpp"
#include "sphcore/case_file.hpp"

namespace cosph::fluid {
namespace {

using testing::Neighbourhood;
using testing::sort_and_find_neighbours;
using testing::water_parameters;

const std::string kDamBreak = std::string(COSPH_SOURCE_DIR) + "/cases/dam_break.pbtxt";

// Water at rest density moving at VELOCITY over a floor of wall particles, no
// gravity and no pressure anywhere: within the water nothing moves relative
// to anything, so any force between water and floor is the walls'
// dissipation. `braking` is the largest deceleration along VELOCITY of a water
// particle away from the block's ends (x in 0.08-0.22 m), where the floor's
// normal is straight up.
struct WaterOverAFloor {
  FluidParticles P;
  Neighbourhood n;
  double braking = 0.0;  // m/s^2
  Vec2 force_on_floor = Vec2::Zero();
  int water = 0;

  WaterOverAFloor(WallFriction wall_friction, const Vec2& velocity) {
    FluidParameters p = water_parameters(0.01);
    p.wall_friction = wall_friction;
    p.B = 0.0;
    const int columns = 30, rows = 6;
    for (int i = 0; i < columns; ++i)
      for (int j = 0; j < rows; ++j) {
        P.add(water, Kind::water, Vec2((i + 0.5) * p.dx, (j + 0.5) * p.dx), p.rho0,
              p.rho0 * p.dx * p.dx);
        P.v.back() = velocity;
        ++water;
      }
    int id = water;
    for (int i = -3; i < columns + 3; ++i)
      for (int layer = 0; layer < 3; ++layer)
        P.add(id++, Kind::wall, Vec2((i + 0.5) * p.dx, -(layer + 0.5) * p.dx), p.rho0,
              p.rho0 * p.dx * p.dx);
    P.first_wall_id = {water};
    sort_and_find_neighbours(P, p, n);
    compute_continuity_and_gradients(P, n.pairs, p);
    for (std::size_t i = 0; i < P.size(); ++i) P.p[i] = 0.0;
    const TaitEquationOfState eos(p.rho0, p.c0);
    compute_wall_pressure(P, n.grid, walls_in_reach(P, n.grid, sph::kernel::kSupport * p.h), p,
                          eos);
    compute_accelerations(P, n.pairs, p);
    const Vec2 along = velocity.normalized();
    for (std::size_t i = 0; i < P.size(); ++i)
      if (P.is_water(i) && P.x[i].x() > 0.08 && P.x[i].x() < 0.22)
        braking = std::max(braking, -P.a[i].dot(along));
    force_on_floor = forces_on_walls(P, n.pairs, p).at(0);
  }
};

const Vec2 kSliding(1.0, 0.0), kFalling(0.0, -1.0);  // m/s

TEST(WallFriction, TheDissipationAgainstAWallBrakesWaterSlidingAlongIt) {
  const WaterOverAFloor with(WallFriction::dissipation, kSliding);
  EXPECT_GT(with.braking, 1.0);              // m/s^2: the first rows are braked
  EXPECT_GT(with.force_on_floor.x(), 1e-3);  // N/m: dragged along by the water
}

TEST(WallFriction, FreeSlipWallsLeaveSlidingWaterAlone) {
  const WaterOverAFloor none(WallFriction::none, kSliding);
  EXPECT_LT(none.braking, 1e-9);
  EXPECT_LT(std::abs(none.force_on_floor.x()), 1e-9);
  // Along the normal only: nothing of sliding along a flat floor either.
  const WaterOverAFloor normal(WallFriction::normal, kSliding);
  EXPECT_LT(normal.braking, 1e-9);
}

TEST(WallFriction, AlongTheNormalOnlyStillDampsWaterRunningIntoTheWall) {
  const WaterOverAFloor with(WallFriction::dissipation, kFalling);
  const WaterOverAFloor normal(WallFriction::normal, kFalling);
  const WaterOverAFloor none(WallFriction::none, kFalling);
  EXPECT_GT(with.braking, 1.0);
  EXPECT_NEAR(normal.braking, with.braking, 1e-9 * with.braking);
  EXPECT_LT(none.braking, 1e-9);
}

TEST(WallFriction, IsReadFromTheCaseAndAnUnknownValueIsRefusedNamingTheField) {
  const auto friction = [](const std::string& setting) {
    return read_fluid_parameters(sph::load_case(kDamBreak, {setting})).wall_friction;
  };
  EXPECT_EQ(read_fluid_parameters(sph::load_case(kDamBreak, {})).wall_friction,
            WallFriction::normal);
  EXPECT_EQ(friction("fluid.wall_friction=dissipation"), WallFriction::dissipation);
  EXPECT_EQ(friction("fluid.wall_friction=none"), WallFriction::none);
  EXPECT_EQ(friction("fluid.wall_friction=normal"), WallFriction::normal);
  try {
    read_fluid_parameters(sph::load_case(kDamBreak, {"fluid.wall_friction=slip"}));
    FAIL() << "an unknown wall friction was accepted";
  } catch (const sph::ConfigError& error) {
    EXPECT_NE(std::string(error.what()).find("fluid.wall_friction"), std::string::npos)
        << error.what();
    EXPECT_NE(std::string(error.what()).find("slip"), std::string::npos) << error.what();
  }
}

}  // namespace
}  // namespace cosph::fluid
